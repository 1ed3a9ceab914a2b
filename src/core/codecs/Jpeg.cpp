// SPDX-License-Identifier: Apache-2.0
// JPEG through libjpeg-turbo. Its errors arrive by longjmp from error_exit: as in Png.cpp, every
// C++ object of a function that calls it is constructed before its setjmp.
#include <csetjmp>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <jpeglib.h>  // after <cstdio>: it uses FILE and size_t without including them
// clang-format off
#include <jerror.h>  // after <jpeglib.h>: the message codes it defines
// clang-format on

#include "core/FirstLine.h"
#include "core/codecs/Codecs.h"

namespace flarekit::codec {

namespace {

struct JpegErrors {
    jpeg_error_mgr manager{};  // first member: libjpeg passes a pointer to it
    std::jmp_buf jump{};
    char message[JMSG_LENGTH_MAX] = {};
    char warning[JMSG_LENGTH_MAX] = {};  //!< the first warning, for one line to the user
};

void onError(j_common_ptr info) {
    auto* errors = reinterpret_cast<JpegErrors*>(info->err);
    info->err->format_message(info, errors->message);
    std::longjmp(errors->jump, 1);
}
//! Every row of the image was decoded (only its end marker may be missing).
bool allRowsRead(j_common_ptr info) {
    if (!info->is_decompressor) return false;
    const auto* d = reinterpret_cast<j_decompress_ptr>(info);
    return d->output_height > 0 && d->output_scanline >= d->output_height;
}

//! Level -1 is a warning. Premature end of data before the last row is an error: libjpeg fills
//! the rows it never got with grey and carries on, so a truncated file (end of file) or a header
//! claiming 4000x4000 over 5 KB (the end marker where data should be) would be flared as a grey
//! slab. Other warnings (a corrupt marker libjpeg skips, extraneous bytes, a missing end marker
//! after the last row) leave a whole image: the first is kept for one warning line.
void onMessage(j_common_ptr info, int level) {
    if (level != -1) return;  // trace messages
    auto* errors = reinterpret_cast<JpegErrors*>(info->err);
    const int code = info->err->msg_code;
    if ((code == JWRN_JPEG_EOF || code == JWRN_HIT_MARKER) && !allRowsRead(info)) {
        info->err->format_message(info, errors->message);
        std::longjmp(errors->jump, 1);
    }
    if (errors->warning[0] == '\0') info->err->format_message(info, errors->warning);
}

struct ReadState {
    JpegErrors errors;
    jpeg_decompress_struct info{};
    bool created = false;
    std::FILE* file = nullptr;
    ~ReadState() {
        if (created) jpeg_destroy_decompress(&info);
        if (file) std::fclose(file);
    }
};

//! The Exif APP1 segment saved by jpeg_save_markers: "Exif\0\0" then a TIFF structure.
int orientationOf(const jpeg_decompress_struct& info) {
    for (jpeg_saved_marker_ptr m = info.marker_list; m; m = m->next) {
        if (m->marker == JPEG_APP0 + 1 && m->data_length > 6 &&
            std::memcmp(m->data, "Exif\0\0", 6) == 0) {
            return exifOrientation(m->data + 6, m->data_length - 6);
        }
    }
    return 1;
}

}  // namespace

namespace {

//! Decodes from `st.file`, or from `bytes` when given; `path` names the image in errors.
Result<Raw> decode(ReadState& st, const std::string& path, const HeaderCheck& check,
                   const std::vector<unsigned char>* bytes) {
    Raw raw;
    Status checked = Ok{};
    st.info.err = jpeg_std_error(&st.errors.manager);
    st.errors.manager.error_exit = onError;
    st.errors.manager.emit_message = onMessage;
    if (setjmp(st.errors.jump)) {
        return invalidInput(path + ": cannot decode image: " + excerpt(st.errors.message, 200));
    }
    jpeg_create_decompress(&st.info);
    st.created = true;
    if (bytes)
        jpeg_mem_src(&st.info, bytes->data(), static_cast<unsigned long>(bytes->size()));
    else
        jpeg_stdio_src(&st.info, st.file);
    jpeg_save_markers(&st.info, JPEG_APP0 + 1, 0xFFFF);
    jpeg_read_header(&st.info, TRUE);
    // CMYK and YCCK (Adobe's inverted inks) need OpenImageIO's conversion; grey stays grey and
    // YCbCr becomes RGB.
    if (st.info.jpeg_color_space == JCS_CMYK || st.info.jpeg_color_space == JCS_YCCK)
        return invalidInput(kUnsupportedLayout);
    st.info.out_color_space = st.info.num_components == 1 ? JCS_GRAYSCALE : JCS_RGB;
    raw.header.width = int(st.info.image_width);
    raw.header.height = int(st.info.image_height);
    raw.header.channels = st.info.num_components == 1 ? 1 : 3;
    raw.header.format = "jpeg";
    checked = check(raw.header);
    if (!checked) return checked.error();
    jpeg_start_decompress(&st.info);
    raw.channels = int(st.info.output_components);
    const std::size_t rowBytes = std::size_t(st.info.output_width) * std::size_t(raw.channels);
    raw.bytes.resize(rowBytes * st.info.output_height);
    while (st.info.output_scanline < st.info.output_height) {
        JSAMPROW row = raw.bytes.data() + std::size_t(st.info.output_scanline) * rowBytes;
        jpeg_read_scanlines(&st.info, &row, 1);
    }
    raw.orientation = orientationOf(st.info);
    jpeg_finish_decompress(&st.info);
    if (st.errors.warning[0] != '\0') raw.warning = excerpt(st.errors.warning, 200);
    return raw;
}

}  // namespace

Result<Raw> readJpeg(const std::string& path, const HeaderCheck& check) {
    ReadState st;
    st.file = std::fopen(path.c_str(), "rb");
    if (!st.file) return ioError(path + ": cannot read: " + std::strerror(errno));
    return decode(st, path, check, nullptr);
}

Result<Raw> decodeJpegBytes(const std::vector<unsigned char>& bytes, const std::string& name,
                            const HeaderCheck& check) {
    ReadState st;
    return decode(st, name, check, &bytes);
}

namespace {

struct WriteState {
    JpegErrors errors;
    jpeg_compress_struct info{};
    bool created = false;
    unsigned char* buffer = nullptr;
    unsigned long size = 0;
    ~WriteState() {
        if (created) jpeg_destroy_compress(&info);
        std::free(buffer);
    }
};

}  // namespace

Result<std::vector<unsigned char>> encodeJpeg(const Samples& s, const EncodeOptions& options) {
    WriteState st;
    std::vector<unsigned char> bytes;
    if (s.type != SampleType::U8 || (s.channels != 1 && s.channels != 3))
        return internalError("JPEG takes 8-bit grey or RGB samples");
    st.info.err = jpeg_std_error(&st.errors.manager);
    st.errors.manager.error_exit = onError;
    st.errors.manager.emit_message = onMessage;
    if (setjmp(st.errors.jump))
        return ioError(std::string("cannot encode JPEG: ") + st.errors.message);
    jpeg_create_compress(&st.info);
    st.created = true;
    jpeg_mem_dest(&st.info, &st.buffer, &st.size);
    st.info.image_width = JDIMENSION(s.width);
    st.info.image_height = JDIMENSION(s.height);
    st.info.input_components = s.channels;
    st.info.in_color_space = s.channels == 1 ? JCS_GRAYSCALE : JCS_RGB;
    jpeg_set_defaults(&st.info);
    jpeg_set_quality(&st.info, options.jpegQuality, TRUE);
    jpeg_start_compress(&st.info, TRUE);
    const std::size_t rowBytes = std::size_t(s.width) * std::size_t(s.channels);
    while (st.info.next_scanline < st.info.image_height) {
        JSAMPROW row = const_cast<JSAMPROW>(static_cast<const unsigned char*>(s.data) +
                                            std::size_t(st.info.next_scanline) * rowBytes);
        jpeg_write_scanlines(&st.info, &row, 1);
    }
    jpeg_finish_compress(&st.info);
    bytes.assign(st.buffer, st.buffer + st.size);
    return bytes;
}

}  // namespace flarekit::codec

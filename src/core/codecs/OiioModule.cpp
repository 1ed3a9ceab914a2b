// SPDX-License-Identifier: Apache-2.0
// The body of libflarekit_oiio.so (see OiioModule.h): OpenImageIO behind the module interface.
// It links nothing of flarekit: limits and messages stay in the core, which passes its check.
#include "core/codecs/OiioModule.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <thread>

#include "core/FirstLine.h"

namespace flarekit::codec {

namespace {

bool declaredLinear(const OIIO::ImageSpec& spec) {
    std::string cs = spec.get_string_attribute("oiio:ColorSpace");
    std::transform(cs.begin(), cs.end(), cs.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return cs == "linear" || cs == "lin_srgb" || cs == "scene_linear";
}

Result<Raw> read(const std::string& path, const HeaderCheck& check) {
    // OpenEXR's and OIIO's own pools: one thread per core.
    OIIO::attribute("threads", int(std::max(1u, std::thread::hardware_concurrency())));
    // Straight (unassociated) alpha in memory: without this hint OIIO's PNG reader multiplies
    // colour by alpha, which would change the bytes `flarekit blend` must use exactly.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path, &config);
    if (!in) {
        std::string why = firstLine(OIIO::geterror());
        return invalidInput(path +
                            ": cannot read image: " + (why.empty() ? "unknown format" : why));
    }
    // OIIO reads a movie as one subimage per frame; taking the first one silently would hide
    // that the rest were ignored.
    if (std::string(in->format_name()).rfind("FFmpeg", 0) == 0) {  // OIIO's "FFmpeg movie"
        return invalidInput(path +
                            ": is a video; flarekit reads still images (take a frame out with "
                            "`ffmpeg -i " +
                            path + " -frames:v 1 frame.png`)");
    }
    const OIIO::ImageSpec& spec = in->spec();
    Raw raw;
    raw.header.width = spec.width;
    raw.header.height = spec.height;
    raw.header.channels = spec.nchannels;
    const auto base = spec.format.basetype;
    raw.header.isFloat = base == OIIO::TypeDesc::HALF || base == OIIO::TypeDesc::FLOAT ||
                         base == OIIO::TypeDesc::DOUBLE;
    raw.header.declaredLinear = declaredLinear(spec);
    raw.header.decodeAs = base == OIIO::TypeDesc::UINT8    ? SampleType::U8
                          : base == OIIO::TypeDesc::UINT16 ? SampleType::U16
                                                           : SampleType::F32;
    raw.header.format = in->format_name();
    if (Status s = check(raw.header); !s) return s.error();
    raw.channels = std::min(spec.nchannels, 4);
    raw.orientation = spec.get_int_attribute("Orientation", 1);
    raw.bytes.resize(raw.sampleCount() * sampleBytes(raw.header.decodeAs));
    const OIIO::TypeDesc type = raw.header.decodeAs == SampleType::U8    ? OIIO::TypeDesc::UINT8
                                : raw.header.decodeAs == SampleType::U16 ? OIIO::TypeDesc::UINT16
                                                                         : OIIO::TypeDesc::FLOAT;
    if (!in->read_image(0, 0, 0, raw.channels, type, raw.bytes.data()))
        return invalidInput(path + ": cannot decode image: " + firstLine(in->geterror()));
    return raw;
}

bool canWrite(const std::string& path, bool* alpha) {
    auto out = OIIO::ImageOutput::create(path);
    if (!out || !out->supports("ioproxy")) return false;
    if (alpha) *alpha = out->supports("alpha");
    return true;
}

Result<std::vector<unsigned char>> encode(const std::string& path, const Samples& s) {
    auto out = OIIO::ImageOutput::create(path);
    if (!out) return internalError(path + ": no OpenImageIO writer");
    const OIIO::TypeDesc type = s.type == SampleType::U8    ? OIIO::TypeDesc::UINT8
                                : s.type == SampleType::U16 ? OIIO::TypeDesc::UINT16
                                                            : OIIO::TypeDesc::FLOAT;
    OIIO::ImageSpec spec(s.width, s.height, s.channels,
                         s.half ? OIIO::TypeDesc(OIIO::TypeDesc::HALF) : type);
    if (s.channels == 2 || s.channels == 4) {
        spec.alpha_channel = s.channels - 1;
        spec.attribute("oiio:UnassociatedAlpha", 1);  // written as held: no division by alpha
    }
    spec.attribute("oiio:ColorSpace", s.type == SampleType::F32 ? "Linear" : s.srgb ? "sRGB" : "");
    spec.attribute("Software", "flarekit");
    std::vector<unsigned char> bytes;
    OIIO::Filesystem::IOVecOutput memory(bytes);
    const OIIO::stride_t stride = s.pixelStride ? OIIO::stride_t(s.pixelStride) : OIIO::AutoStride;
    if (!out->set_ioproxy(&memory) || !out->open(path, spec) ||
        !out->write_image(type, s.data, stride) || !out->close()) {
        return ioError(path + ": cannot encode: " + firstLine(out->geterror()));
    }
    return bytes;
}

bool renderText(float* rgba, int width, int height, int x, int y, const std::string& text, int size,
                const std::string& fontPath, const float colour[4]) {
    OIIO::ImageSpec spec(width, height, 4, OIIO::TypeDesc::FLOAT);
    OIIO::ImageBuf canvas(spec, rgba);  // wraps the caller's pixels, no copy
    const bool drawn = OIIO::ImageBufAlgo::render_text(canvas, x, y, text, size, fontPath,
                                                       OIIO::cspan<float>(colour, 4));
    OIIO::geterror();  // clear a font error; the result reports it
    return drawn;
}

const OiioModule kModule{kOiioModuleAbi, sizeof(Raw), sizeof(Samples), read,
                         canWrite,       encode,      renderText};

}  // namespace

}  // namespace flarekit::codec

extern "C" __attribute__((visibility("default"))) const flarekit::codec::OiioModule*
flarekit_oiio_module() {
    return &flarekit::codec::kModule;
}

// SPDX-License-Identifier: Apache-2.0
// What an EXR holds beyond the RGBA flarekit works on, kept from the read for the write: the
// header (attributes such as timeCode, camera data and custom ones; the data and display
// windows; compression) and the other channels' pixels in their own types.
#pragma once

#include <ImfChannelList.h>
#include <ImfHeader.h>

#include <memory>
#include <string>
#include <vector>

namespace flarekit {

struct ExrExtraChannel {
    std::string name;
    Imf::Channel channel;
    std::vector<char> pixels;  //!< the data window, rows top first, samples of channel.type
};

//! A multi-part input (stereo views, a compositor's layers): every part's header and the file the
//! parts not flared are copied from, chunk for chunk, when the output is written.
struct ExrParts {
    std::string source;                //!< the input file, read again at the write
    int chosen = 0;                    //!< the part read into the image
    std::vector<Imf::Header> headers;  //!< every part's, in the file's order
};

struct ExrExtras {
    Imf::Header header;  //!< the input's whole header (the chosen part's)
    std::vector<ExrExtraChannel> channels;
    bool rgbHalf = true;  //!< the colour channels were half floats
    std::string layer;    //!< the colour channels' layer ("diffuse." for diffuse.R, ...) or ""
    std::shared_ptr<const ExrParts> parts;  //!< null: a single-part file
};

}  // namespace flarekit

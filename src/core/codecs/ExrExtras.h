// SPDX-License-Identifier: Apache-2.0
// What an EXR holds beyond the RGBA flarekit works on, kept from the read for the write: the
// header (attributes such as timeCode, camera data and custom ones; the data and display
// windows; compression) and the other channels' pixels in their own types.
#pragma once

#include <ImfChannelList.h>
#include <ImfHeader.h>

#include <string>
#include <vector>

namespace flarekit {

struct ExrExtraChannel {
    std::string name;
    Imf::Channel channel;
    std::vector<char> pixels;  //!< the data window, rows top first, samples of channel.type
};

struct ExrExtras {
    Imf::Header header;  //!< the input's whole header
    std::vector<ExrExtraChannel> channels;
    bool rgbHalf = true;  //!< the colour channels were half floats
};

}  // namespace flarekit

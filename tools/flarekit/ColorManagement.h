// SPDX-License-Identifier: Apache-2.0
// Colour spaces in and out through OpenColorIO: the input converted from its colour space to
// the config's scene_linear (flarekit's working space, linear Rec.709 in the shipped config),
// the result from there to the output's. Without the options nothing changes: 8/16-bit files
// are sRGB, float files scene-linear Rec.709.
#pragma once

#include <CLI/CLI.hpp>

#include <memory>
#include <string>

#include "flarekit/Image.h"
#include "flarekit/ImageIO.h"
#include "flarekit/Result.h"

namespace flarekit::cli {

struct ColorArgs {
    std::string in, out;  //!< --colorspace-in / --colorspace-out; empty: flarekit's defaults
    std::string config;   //!< --ocio-config; empty: $OCIO
    bool enabled() const { return !in.empty() || !out.empty(); }
};
void addColorOptions(CLI::App* cmd, ColorArgs& args);

//! The processors of one run (built once; applying them is thread-safe, as a shot needs).
class ColorManagement {
  public:
    //! The config and both colour spaces checked: an unknown name is one line listing the
    //! config's colour spaces. Null when neither space is given (flarekit's defaults).
    static Result<std::shared_ptr<const ColorManagement>> create(const ColorArgs& args);
    //! A read image to the working space: `loaded` as decoded (an integer file's sRGB decode
    //! taken back first, so the file's own code values are converted).
    void toWorking(LoadedImage& loaded) const;
    //! The working-space result to the output's colour space; `options` then writes the values
    //! as they are (no second sRGB curve on integer formats).
    void toOutput(Image& image, WriteOptions& options) const;

    struct Processors;
    ~ColorManagement();

  private:
    ColorManagement() = default;
    std::unique_ptr<Processors> m_processors;
    std::string m_outName;  //!< --colorspace-out, the output files' tag
};

}  // namespace flarekit::cli

// SPDX-License-Identifier: Apache-2.0
#include "ColorManagement.h"

#include <OpenColorIO/OpenColorIO.h>

#include <cstdlib>

#include "core/InstallPaths.h"
#include "core/Parallel.h"
#include "flarekit/Color.h"

namespace OCIO = OCIO_NAMESPACE;

namespace flarekit::cli {

struct ColorManagement::Processors {
    OCIO::ConstCPUProcessorRcPtr in, out;  //!< null: that side keeps flarekit's default
};

ColorManagement::~ColorManagement() = default;

void addColorOptions(CLI::App* cmd, ColorArgs& args) {
    cmd->add_option("--colorspace-in", args.in,
                    "the input's colour space in the OCIO config (default: sRGB for 8/16-bit "
                    "files, scene-linear Rec.709 for float files)");
    cmd->add_option("--colorspace-out", args.out,
                    "the output's colour space in the OCIO config (default: as the input's kind)");
    cmd->add_option("--ocio-config", args.config,
                    "OpenColorIO config file (default: $OCIO, else the shipped "
                    "presets/ocio/flarekit.ocio; an ACES config works too)");
}

Result<std::shared_ptr<const ColorManagement>> ColorManagement::create(const ColorArgs& args) {
    if (!args.enabled()) return std::shared_ptr<const ColorManagement>();
    std::string path = args.config;
    if (path.empty())
        if (const char* env = std::getenv("OCIO")) path = env;
    if (path.empty()) path = shippedOcioConfig().string();
    if (path.empty())
        return invalidInput(
            "--colorspace-in/--colorspace-out need an OpenColorIO config: set $OCIO or "
            "--ocio-config (the shipped presets/ocio/flarekit.ocio was not found beside flarekit)");
    OCIO::ConstConfigRcPtr config;
    try {
        OCIO::ClearAllCaches();
        config = OCIO::Config::CreateFromFile(path.c_str());
        config->validate();
    } catch (const std::exception& e) {
        return invalidInput(path + ": not a usable OpenColorIO config: " + e.what());
    }
    auto known = [&] {
        std::string names;
        for (int i = 0; i < config->getNumColorSpaces(); ++i)
            names += std::string(i ? ", " : "") + config->getColorSpaceNameByIndex(i);
        return names;
    };
    for (const auto& [option, name] :
         {std::pair{"--colorspace-in", args.in}, std::pair{"--colorspace-out", args.out}}) {
        if (!name.empty() && !config->getColorSpace(name.c_str()))
            return invalidInput(std::string(option) + ": '" + name + "' is not a colour space of " +
                                path + "; it has: " + known());
    }
    std::shared_ptr<ColorManagement> cm(new ColorManagement);
    cm->m_processors = std::make_unique<Processors>();
    try {
        if (!args.in.empty())
            cm->m_processors->in = config->getProcessor(args.in.c_str(), OCIO::ROLE_SCENE_LINEAR)
                                       ->getDefaultCPUProcessor();
        cm->m_outName = args.out;
        if (!args.out.empty())
            cm->m_processors->out = config->getProcessor(OCIO::ROLE_SCENE_LINEAR, args.out.c_str())
                                        ->getDefaultCPUProcessor();
    } catch (const std::exception& e) {
        return invalidInput(path + ": " + e.what());
    }
    return std::shared_ptr<const ColorManagement>(std::move(cm));
}

namespace {
//! RGBA rows in place through `cpu`, in chunks on every core.
void applyRgba(const OCIO::ConstCPUProcessorRcPtr& cpu, Image& image) {
    const long w = image.width();
    // 16 rows a task: the processor's per-call set-up stays small next to the pixels.
    parallelFor(0, image.height(), 16, [&](int y0, int y1) {
        OCIO::PackedImageDesc rows(image.row(y0), w, long(y1 - y0), 4);
        cpu->apply(rows);
    });
}
}  // namespace

void ColorManagement::toWorking(LoadedImage& loaded) const {
    if (!m_processors->in) return;
    if (!loaded.wasFloat) {
        // The reader sRGB-decoded the file's codes: encode them back (exactly, in float) so the
        // config converts the file's own values.
        float* p = loaded.image.data();
        for (std::size_t i = 0; i < loaded.image.pixelCount() * 4; ++i)
            if (i % 4 != 3) p[i] = linearToSrgb(p[i]);
    }
    applyRgba(m_processors->in, loaded.image);
}

void ColorManagement::toOutput(Image& image, WriteOptions& options) const {
    if (!m_processors->out) return;
    applyRgba(m_processors->out, image);
    options.srgbEncode = false;
    options.colorSpace = m_outName;
}

}  // namespace flarekit::cli

// SPDX-License-Identifier: Apache-2.0
#include "flarekit/ocio/OcioTransform.h"

#include <OpenColorIO/OpenColorIO.h>

#include <cstdlib>

#include "core/InstallPaths.h"
#include "core/Parallel.h"
#include "flarekit/Color.h"

namespace OCIO = OCIO_NAMESPACE;

namespace flarekit {

namespace {
class OcioTransform final : public ColorTransform {
  public:
    void toWorking(LoadedImage& loaded) const override;
    void toOutput(Image& image, WriteOptions& options) const override;

    OCIO::ConstCPUProcessorRcPtr in, out;  //!< null: that side keeps flarekit's default
    std::string outName;                   //!< the output's colour space, its files' tag
};
}  // namespace

Result<std::shared_ptr<const ColorTransform>> createOcioTransform(const OcioSettings& args) {
    if (!args.enabled()) return std::shared_ptr<const ColorTransform>();
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
    auto cm = std::make_shared<OcioTransform>();
    try {
        if (!args.in.empty())
            cm->in = config->getProcessor(args.in.c_str(), OCIO::ROLE_SCENE_LINEAR)
                         ->getDefaultCPUProcessor();
        cm->outName = args.out;
        if (!args.out.empty())
            cm->out = config->getProcessor(OCIO::ROLE_SCENE_LINEAR, args.out.c_str())
                          ->getDefaultCPUProcessor();
    } catch (const std::exception& e) {
        return invalidInput(path + ": " + e.what());
    }
    return std::shared_ptr<const ColorTransform>(std::move(cm));
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

void OcioTransform::toWorking(LoadedImage& loaded) const {
    if (!in) return;
    if (!loaded.wasFloat) {
        // The reader sRGB-decoded the file's codes: encode them back (exactly, in float) so the
        // config converts the file's own values.
        float* p = loaded.image.data();
        for (std::size_t i = 0; i < loaded.image.pixelCount() * 4; ++i)
            if (i % 4 != 3) p[i] = linearToSrgb(p[i]);
    }
    applyRgba(in, loaded.image);
}

void OcioTransform::toOutput(Image& image, WriteOptions& options) const {
    if (!out) return;
    applyRgba(out, image);
    options.srgbEncode = false;
    options.colorSpace = outName;
}

}  // namespace flarekit

// SPDX-License-Identifier: Apache-2.0
// Babylon.js LensFlareSystem, as its serialize() writes it: {"borderLimit", "flares": [{"size",
// "position", "color", "textureName"}], ...}. Its renderer (lensFlareSystem.ts) places a flare at
// centre - (centre - light) x position, so position is flarekit's t (1 - u); it draws a quad of
// half width size/2 in clip space and of height size x (width / height) / 2, a square whose
// half side is size x W / 4 pixels: a flare's radius is size x aspect / 4 frame heights.
#include "convert/ConvertCommon.h"
#include "convert/ExtensionBlock.h"
#include "flarekit/ParamText.h"

namespace flarekit::convert {

namespace {
float radiusFromBabylonSize(double size, float aspect) {
    return float(size * double(aspect) / 4.0);
}
double babylonSizeFromRadius(float radius, float aspect) {
    return double(radius) * 4.0 / double(aspect);
}
}  // namespace

Result<FlareAsset> readBabylon(const json& doc, ImportContext& ctx) {
    const JsonPlace top(ctx.path);
    const auto flares = doc.find("flares");
    if (flares == doc.end() || !flares->is_array() || flares->empty() ||
        flares->size() > kMaxPresetElements) {
        return (top / "flares")
            .fail("expected an array of 1 to " + std::to_string(kMaxPresetElements) +
                  " flares of a Babylon.js LensFlareSystem");
    }
    FlareAsset asset;
    asset.sprite.name = fieldOr(doc, "name", fs::path(ctx.path).stem().string());
    for (std::size_t i = 0; i < flares->size(); ++i) {
        const json& f = (*flares)[i];
        const JsonPlace at = (top / "flares").index(i);
        if (!f.is_object()) return at.fail("expected an object, got " + jsonExcerpt(f));
        auto size = readNumber(f, "size", at, std::nullopt, 0, 100);
        auto position = readNumber(f, "position", at, std::nullopt, -8, 8);
        if (!size) return size.error();
        if (!position) return position.error();
        const auto colorIt = f.find("color");
        Rgb color{1, 1, 1};
        if (colorIt != f.end()) {
            auto c = readRgb(*colorIt, at / "color");
            if (!c) return c.error();
            color = *c;
        }
        ElementParams e = defaultElement(ElementType::Image);
        if (const auto ext = f.find("flarekit"); ext != f.end()) {
            auto restored = elementFromExtension(*ext, at / "flarekit");
            if (!restored) return restored.error();
            e = *restored;  // the procedural element this flare was baked from
        } else {
            auto texture = readString(f, "textureName", at, std::nullopt);
            if (!texture) return texture.error();
            if (Status s = loadTexture(ctx, *texture, at / "textureName", e); !s) return s.error();
            e.size = radiusFromBabylonSize(*size, ctx.options.aspect);
            e.color = color;
        }
        e.t = float(*position);
        e.source = sourceBlock(
            FlareFormat::Babylon,
            unmappedFields(f, {"size", "position", "color", "textureName", "flarekit"}));
        asset.sprite.elements.push_back(std::move(e));
    }
    const json rest = unmappedFields(doc, {"flares", "name"});
    if (rest.contains("borderLimit") && rest["borderLimit"] != 0)
        ctx.warn("borderLimit " + rest["borderLimit"].dump() +
                 ": flarekit does not fade flares toward the frame border; kept in source");
    asset.sprite.source = sourceBlock(FlareFormat::Babylon, rest);
    return asset;
}

Result<std::string> writeBabylon(const Preset& preset, ExportContext& ctx) {
    json doc = sourceFields(preset.source, FlareFormat::Babylon);
    doc["name"] = preset.name;
    if (!doc.contains("borderLimit")) doc["borderLimit"] = 300;  // Babylon's own default
    json flares = json::array();
    for (std::size_t i = 0; i < preset.elements.size(); ++i) {
        const ElementParams& e = preset.elements[i];
        const std::string label = elementLabel(e, i);
        if (!e.visible) {
            ctx.warn(label + "switched off: Babylon.js has no hidden flares; left out");
            continue;
        }
        json f = sourceFields(e.source, FlareFormat::Babylon);
        const TexturedQuad q = texturedQuad(e, i, preset.intensity, "Babylon.js", ctx);
        f["position"] = e.t;
        f["textureName"] = q.texture;
        f["size"] = babylonSizeFromRadius(q.radius, ctx.options.aspect);
        f["color"] = {q.color[0], q.color[1], q.color[2]};
        if (!q.extension.is_null()) f["flarekit"] = q.extension;
        flares.push_back(std::move(f));
    }
    if (flares.empty()) return invalidInput(ctx.path + ": no visible element to write");
    doc["flares"] = std::move(flares);
    return dumpByLine(doc, "flares");
}

}  // namespace flarekit::convert

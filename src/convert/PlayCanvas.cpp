// SPDX-License-Identifier: Apache-2.0
// PlayCanvas LensFlareLook: PlayCanvas ships no flare of its own; its lens-flare scripts read a
// JSON look of {"elements": [{"shape", "offset", "size", "aspect", "rotation", "autoRotate",
// "color", "intensity", "count", "spread"}]}. `offset` is u (0 on the light, 1 at the centre,
// 2 at the mirror point); `size` is the element's diameter as a fraction of the screen height;
// `rotation` is degrees clockwise on screen; `count` copies are spread evenly over `spread`
// (in offset units) centred on `offset`. `shape` names a procedural shape or a texture file.
#include <cmath>

#include "convert/ConvertCommon.h"
#include "convert/ExtensionBlock.h"

namespace flarekit::convert {

namespace {

struct ShapeName {
    const char* name;
    ElementType type;
};
//! PlayCanvas shapes and the flarekit elements that draw them.
constexpr ShapeName kShapes[] = {
    {"circle", ElementType::Disc},     {"ring", ElementType::Ring},
    {"polygon", ElementType::Polygon}, {"glow", ElementType::Glow},
    {"streaks", ElementType::Streaks}, {"rays", ElementType::Rays},
};
constexpr const char* kShapeList =
    "\"circle\", \"ring\", \"polygon\", \"glow\", \"streaks\", \"rays\" or an image file";

bool isImageFile(const std::string& s) {
    const std::string ext = fs::path(s).extension().string();
    for (const char* e : {".png", ".jpg", ".jpeg", ".webp", ".exr", ".hdr", ".tif", ".tiff"})
        if (ext == e) return true;
    return false;
}

const char* shapeOf(ElementType type) {
    for (const ShapeName& s : kShapes)
        if (s.type == type) return s.name;
    return nullptr;
}

}  // namespace

Result<FlareAsset> readPlayCanvas(const json& doc, ImportContext& ctx) {
    const JsonPlace top(ctx.path);
    const auto elements = doc.find("elements");
    if (elements == doc.end() || !elements->is_array() || elements->empty()) {
        return (top / "elements").fail("expected an array of PlayCanvas lens-flare elements");
    }
    FlareAsset asset;
    asset.sprite.name = fieldOr(doc, "name", fs::path(ctx.path).stem().string());
    auto intensity = readNumber(doc, "intensity", top, 1.0, 0, 1000);
    if (!intensity) return intensity.error();
    asset.sprite.intensity = float(*intensity);
    for (std::size_t i = 0; i < elements->size(); ++i) {
        const json& f = (*elements)[i];
        const JsonPlace at = (top / "elements").index(i);
        if (!f.is_object()) return at.fail("expected an object, got " + jsonExcerpt(f));
        auto shape = readString(f, "shape", at, std::string("circle"));
        if (!shape) return shape.error();
        ElementParams e;
        const auto ext = f.find("flarekit");
        if (ext != f.end()) {
            auto restored = elementFromExtension(*ext, at / "flarekit");
            if (!restored) return restored.error();
            e = *restored;
        } else if (isImageFile(*shape)) {
            e = defaultElement(ElementType::Image);
            if (Status s = loadTexture(ctx, *shape, at / "shape", e); !s) return s.error();
        } else {
            const ShapeName* known = nullptr;
            for (const ShapeName& s : kShapes)
                if (*shape == s.name) known = &s;
            if (!known)
                return (at / "shape")
                    .fail(std::string("expected ") + kShapeList + ", got " +
                          jsonExcerpt(f["shape"]));
            e = defaultElement(known->type);
        }
        auto offset = readNumber(f, "offset", at, 0.0, -8, 8);
        auto size = readNumber(f, "size", at, 0.2, 0, 8);
        auto aspect = readNumber(f, "aspect", at, 1.0, 0.05, 20);
        auto rotation = readNumber(f, "rotation", at, 0.0, -360, 360);
        auto autoRotate = readBool(f, "autoRotate", at, false);
        auto gain = readNumber(f, "intensity", at, 1.0, 0, 1000);
        auto count = readInt(f, "count", at, 1, 1, int(kMaxPresetElements));
        auto spread = readNumber(f, "spread", at, 0.0, -16, 16);
        auto sides = readInt(f, "sides", at, e.blades, 3, 32);
        auto roundness = readNumber(f, "roundness", at, e.roundness, 0, 1);
        if (auto err =
                firstError(offset, size, aspect, rotation, autoRotate, gain, count, spread, sides))
            return *err;
        if (const auto c = f.find("color"); c != f.end()) {
            auto rgb = readRgb(*c, at / "color");
            if (!rgb) return rgb.error();
            e.color = *rgb;
            // A shape without flarekit's own keys is one colour, as PlayCanvas draws it.
            if (e.type != ElementType::Image && ext == f.end()) e.innerColor.reset();
        }
        e.size = float(*size / 2.0);
        e.aspect = float(*aspect);
        e.rotationDeg = float(*rotation);
        e.intensity = float(*gain);
        if (e.type == ElementType::Polygon) e.blades = *sides, e.roundness = float(*roundness);
        if (*autoRotate)
            ctx.warn("elements[" + std::to_string(i) +
                     "].autoRotate: flarekit does not turn elements toward the light; kept in "
                     "source");
        json kept = unmappedFields(f, {"shape", "offset", "size", "aspect", "rotation", "color",
                                       "intensity", "sides", "roundness", "flarekit"});
        for (int c = 0; c < *count; ++c) {
            if (asset.sprite.elements.size() >= kMaxPresetElements)
                return at.fail("expected at most " + std::to_string(kMaxPresetElements) +
                               " elements in all (counting copies)");
            ElementParams copy = e;
            const double u =
                *count > 1 ? *offset + (double(c) / (*count - 1) - 0.5) * *spread : *offset;
            copy.t = tFromU(u);
            json block = json::parse(sourceBlock(FlareFormat::PlayCanvas, kept), nullptr, false);
            if (c > 0) block = {{"format", "playcanvas"}, {"copy", true}};
            copy.source = block.is_object() ? block.dump() : std::string();
            asset.sprite.elements.push_back(std::move(copy));
        }
    }
    asset.sprite.source = sourceBlock(FlareFormat::PlayCanvas,
                                      unmappedFields(doc, {"elements", "name", "intensity"}));
    return asset;
}

Result<std::string> writePlayCanvas(const Preset& preset, ExportContext& ctx) {
    json doc = sourceFields(preset.source, FlareFormat::PlayCanvas);
    doc["name"] = preset.name;
    doc["intensity"] = preset.intensity;
    json elements = json::array();
    for (std::size_t i = 0; i < preset.elements.size(); ++i) {
        const ElementParams& e = preset.elements[i];
        if (isCountCopy(e)) continue;  // written as its first element's count
        const std::string label = elementLabel(e, i);
        if (!e.visible) {
            ctx.warn(label + "switched off: a LensFlareLook has no hidden elements; left out");
            continue;
        }
        json f = sourceFields(e.source, FlareFormat::PlayCanvas);
        const int count = fieldOr(f, "count", 1);
        const double spread = fieldOr(f, "spread", 0.0);
        f["offset"] = uFromT(e.t) + (count > 1 ? spread / 2.0 : 0.0);
        f["size"] = double(e.size) * 2.0;
        f["aspect"] = e.aspect;
        f["rotation"] = e.rotationDeg;
        f["color"] = {e.color[0], e.color[1], e.color[2]};
        f["intensity"] = e.intensity;
        if (e.type == ElementType::Image) {
            f["shape"] = ctx.addCopy(e.texture);
        } else if (const char* shape = shapeOf(e.type)) {
            f["shape"] = shape;
            if (e.type == ElementType::Polygon) {
                f["sides"] = e.blades;
                if (e.roundness > 0.f) f["roundness"] = e.roundness;
            }
            // Only what the look's own keys do not say.
            json ext = elementExtension(e);
            for (const char* k :
                 {"t", "size", "aspect", "rotation", "color", "intensity", "blades", "roundness"})
                ext.erase(k);
            if (ext.size() > 1) f["flarekit"] = std::move(ext);
        } else {
            float share = 1.f, gain = 1.f;
            f["shape"] = ctx.addBaked(e, int(i), share, gain);
            f["size"] = double(e.size / share) * 2.0;
            f["color"] = {1, 1, 1};
            f["intensity"] = gain;
            f["flarekit"] = elementExtension(e);
            ctx.warn(label + "baked into a texture: a LensFlareLook has no " +
                     std::string(elementTypeName(e.type)) + " shape");
        }
        if (e.blend != BlendMode::Add)
            ctx.warn(label + "blend " + std::string(kBlendModeNames[int(e.blend)]) +
                     ": a LensFlareLook adds every element");
        elements.push_back(std::move(f));
    }
    if (elements.empty()) return invalidInput(ctx.path + ": no visible element to write");
    doc["elements"] = std::move(elements);
    return dumpByLine(doc, "elements");
}

}  // namespace flarekit::convert

// SPDX-License-Identifier: Apache-2.0
// three.js Lensflare (examples/jsm/objects/Lensflare.js): a Lensflare holds LensflareElement(
// texture, size, distance, color). three.js has no file format for it, so flarekit reads and
// writes the JSON that lists those constructor arguments: {"elements": [{"texture", "size",
// "distance", "color"}]}. Its shader places an element at light + (-2 light) x distance in clip
// space (light at distance 0, centre at 0.5, mirror point at 1): distance = u / 2. Its quad is
// `size` pixels a side (scale = size / viewport), so the radius is size / 2 pixels, converted
// at the reference frame height.
#include <cmath>

#include "convert/ConvertCommon.h"
#include "convert/ExtensionBlock.h"

namespace flarekit::convert {

namespace {
//! three.js colours given as hex ("#ffcc88", 0xffcc88) are sRGB and converted to linear, as
//! three.js r152+ does with its colour management on; arrays are the linear r, g, b it stores.
Result<Rgb> readThreeColor(const json& v, const JsonPlace& at) {
    auto fromHex = [](unsigned long hex) {
        Rgb c;
        for (int i = 0; i < 3; ++i) {
            const float s = float((hex >> (16 - 8 * i)) & 0xff) / 255.f;
            c[std::size_t(i)] = s <= 0.04045f ? s / 12.92f : std::pow((s + 0.055f) / 1.055f, 2.4f);
        }
        return c;
    };
    if (v.is_number_unsigned() && v.get<unsigned long>() <= 0xffffff)
        return fromHex(v.get<unsigned long>());
    if (v.is_string()) {
        const std::string s = v.get<std::string>();
        if (s.size() == 7 && s[0] == '#' &&
            s.find_first_not_of("0123456789abcdefABCDEF", 1) == std::string::npos)
            return fromHex(std::stoul(s.substr(1), nullptr, 16));
        return at.fail("expected a colour \"#rrggbb\", 0xrrggbb or [r, g, b], got " +
                       jsonExcerpt(v));
    }
    return readRgb(v, at);
}
}  // namespace

Result<FlareAsset> readThree(const json& doc, ImportContext& ctx) {
    const JsonPlace top(ctx.path);
    const auto elements = doc.find("elements");
    if (elements == doc.end() || !elements->is_array() || elements->empty() ||
        elements->size() > kMaxPresetElements) {
        return (top / "elements")
            .fail("expected an array of 1 to " + std::to_string(kMaxPresetElements) +
                  " three.js LensflareElements");
    }
    const double height = ctx.options.referenceHeight;
    FlareAsset asset;
    asset.sprite.name = fieldOr(doc, "name", fs::path(ctx.path).stem().string());
    for (std::size_t i = 0; i < elements->size(); ++i) {
        const json& f = (*elements)[i];
        const JsonPlace at = (top / "elements").index(i);
        if (!f.is_object()) return at.fail("expected an object, got " + jsonExcerpt(f));
        // LensflareElement's own defaults: size 1, distance 0, colour white.
        auto size = readNumber(f, "size", at, 1.0, 0, 1e5);
        auto distance = readNumber(f, "distance", at, 0.0, -4, 4);
        if (!size) return size.error();
        if (!distance) return distance.error();
        Rgb color{1, 1, 1};
        if (const auto c = f.find("color"); c != f.end()) {
            auto rgb = readThreeColor(*c, at / "color");
            if (!rgb) return rgb.error();
            color = *rgb;
        }
        ElementParams e = defaultElement(ElementType::Image);
        if (const auto ext = f.find("flarekit"); ext != f.end()) {
            auto restored = elementFromExtension(*ext, at / "flarekit");
            if (!restored) return restored.error();
            e = *restored;
        } else {
            auto texture = readString(f, "texture", at, std::nullopt);
            if (!texture) return texture.error();
            if (Status s = loadTexture(ctx, *texture, at / "texture", e); !s) return s.error();
            e.size = float(*size / 2.0 / height);
            e.color = color;
        }
        e.t = tFromU(2.0 * *distance);
        e.source =
            sourceBlock(FlareFormat::Three,
                        unmappedFields(f, {"texture", "size", "distance", "color", "flarekit"}));
        asset.sprite.elements.push_back(std::move(e));
    }
    asset.sprite.source =
        sourceBlock(FlareFormat::Three, unmappedFields(doc, {"elements", "name"}));
    return asset;
}

Result<std::string> writeThree(const Preset& preset, ExportContext& ctx) {
    json doc = sourceFields(preset.source, FlareFormat::Three);
    doc["name"] = preset.name;
    const double height = ctx.options.referenceHeight;
    json elements = json::array();
    for (std::size_t i = 0; i < preset.elements.size(); ++i) {
        const ElementParams& e = preset.elements[i];
        const std::string label = elementLabel(e, i);
        if (!e.visible) {
            ctx.warn(label + "switched off: three.js has no hidden elements; left out");
            continue;
        }
        json f = sourceFields(e.source, FlareFormat::Three);
        const TexturedQuad q = texturedQuad(e, i, preset.intensity, "three.js's Lensflare", ctx);
        f["distance"] = uFromT(e.t) / 2.0;
        f["texture"] = q.texture;
        f["size"] = double(q.radius) * 2.0 * height;
        f["color"] = {q.color[0], q.color[1], q.color[2]};
        if (!q.extension.is_null()) f["flarekit"] = q.extension;
        elements.push_back(std::move(f));
    }
    if (elements.empty()) return invalidInput(ctx.path + ": no visible element to write");
    doc["elements"] = std::move(elements);
    return dumpByLine(doc, "elements");
}

}  // namespace flarekit::convert

// SPDX-License-Identifier: Apache-2.0
#include "convert/ExtensionBlock.h"

namespace flarekit::convert {

json elementExtension(const ElementParams& e) {
    json out =
        writeParams<ElementParams>(e, kElementParams, defaultElement(e.type), typeBit(e.type));
    out["type"] = std::string(elementTypeName(e.type));
    // One colour where the type's default has a gradient: say so, or reading it back would
    // bring the default's inner colour back.
    if (!e.innerColor && defaultElement(e.type).innerColor)
        out["inner_color"] = {e.color[0], e.color[1], e.color[2]};
    return out;
}

Result<ElementParams> elementFromExtension(const json& block, const JsonPlace& at) {
    if (!block.is_object()) return at.fail("expected an object, got " + jsonExcerpt(block));
    const auto type = block.contains("type") && block["type"].is_string()
                          ? parseElementType(block["type"].get<std::string>())
                          : std::nullopt;
    if (!type || *type == ElementType::Image)
        return (at / "type")
            .fail("expected a procedural element type, got " +
                  jsonExcerpt(block.contains("type") ? block["type"] : json()));
    ElementParams e = defaultElement(*type);
    if (auto err = readParams<ElementParams>(block, kElementParams, e, at, {"type"}, typeBit(*type),
                                             elementTypeName(*type)))
        return *err;
    if (Status s = validateParams<ElementParams>(e, kElementParams, at.at() + ".", typeBit(*type));
        !s)
        return invalidInput(at.source() + ": " + s.error().message);
    return e;
}

}  // namespace flarekit::convert

// The one description of every preset parameter: JSON key, kind, range, the element types it
// applies to, and its documentation. Preset validation and the parameter reference
// (`flarekit presets --params`, docs/presets.md) both read it.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <variant>

#include "flarekit/Elements.h"

namespace flarekit {

enum class FieldKind { Number, Integer, Seed, Color, OptionalColor, Blend };

struct FieldSpec {
    std::string_view key;
    FieldKind kind;
    double min, max;           //!< inclusive range (per component for colours)
    std::uint32_t types;       //!< bit i set: applies to ElementType(i)
    std::variant<float ElementParams::*, int ElementParams::*, std::uint32_t ElementParams::*,
                 Rgb ElementParams::*, std::optional<Rgb> ElementParams::*, BlendMode ElementParams::*>
        member;
    std::string_view unit;
    std::string_view doc;
};

inline constexpr std::uint32_t kAllTypes = (1u << kElementTypeCount) - 1;
inline constexpr std::uint32_t typeBit(ElementType t) { return 1u << unsigned(t); }

std::span<const FieldSpec> elementFields();
//! Per-type defaults: ElementParams{} with the fields a type needs set to what looks right.
ElementParams defaultElement(ElementType type);

}  // namespace flarekit

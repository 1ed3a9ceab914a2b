// SPDX-License-Identifier: Apache-2.0
// A Dear ImGui widget for each parameter of a table (flarekit/Param.h): the slider's range, the
// unit, the help in the tooltip and the default all come from the one description the JSON
// reader, the CLI and the docs use, so the studio never restates a range.
#pragma once

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <string>

#include "flarekit/ParamText.h"

namespace flarekit::studio {

//! The tooltip of a parameter: its help, unit, accepted values and default.
template <class Owner>
std::string paramTooltip(const Param<Owner>& p, const Owner& defaults) {
    std::string tip = std::string(p.help);
    if (!p.unit.empty()) tip += joinText("\nunit: ", p.unit);
    tip += "\naccepts " + expectedText(p);
    tip += "\ndefault: " + valueText(p, p.get(defaults));
    return tip;
}

//! Ranges this wide are dragged on a logarithmic scale (an intensity of 0 to 1000: a linear
//! slider would spend all but its first pixels above 10).
inline bool wantsLogScale(double min, double max) {
    return min >= 0 && max >= 100;
}

//! One parameter's widget; true when the user changed the value this frame.
template <class Owner>
bool paramWidget(const Param<Owner>& p, Owner& owner, const Owner& defaults) {
    ParamValue v = p.get(owner);
    const std::string label = std::string(p.key);
    bool changed = false;
    const ImGuiSliderFlags flags =
        ImGuiSliderFlags_AlwaysClamp |
        (wantsLogScale(p.min, p.max) ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None);
    switch (p.type) {
        case ParamType::Number: {
            float f = float(v.number);
            changed =
                ImGui::SliderFloat(label.c_str(), &f, float(p.min), float(p.max), "%.4g", flags);
            if (p.openMin && f <= float(p.min)) f = std::nextafter(float(p.min), float(p.max));
            v.number = f;
            break;
        }
        case ParamType::Integer: {
            int i = int(v.number);
            changed = ImGui::SliderInt(label.c_str(), &i, int(p.min), int(p.max), "%d", flags);
            v.number = i;
            break;
        }
        case ParamType::Seed: {
            ImU32 s = ImU32(v.number);
            changed = ImGui::InputScalar(label.c_str(), ImGuiDataType_U32, &s);
            v.number = s;
            break;
        }
        case ParamType::Bool: {
            bool b = v.number != 0;
            changed = ImGui::Checkbox(label.c_str(), &b);
            v.number = b ? 1 : 0;
            break;
        }
        case ParamType::Choice: {
            int i = int(v.number);
            if (ImGui::BeginCombo(label.c_str(), std::string(p.choices[std::size_t(i)]).c_str())) {
                for (std::size_t c = 0; c < p.choices.size(); ++c) {
                    if (ImGui::Selectable(std::string(p.choices[c]).c_str(), int(c) == i))
                        i = int(c), changed = true;
                }
                ImGui::EndCombo();
            }
            v.number = i;
            break;
        }
        case ParamType::Color:
        case ParamType::OptionalColor: {
            if (p.type == ParamType::OptionalColor) {
                bool set = v.hasColor;
                if (ImGui::Checkbox(("##has_" + label).c_str(), &set)) {
                    changed = true;
                    v.hasColor = set;
                    if (set)
                        v.color = p.get(defaults).hasColor ? p.get(defaults).color : Rgb{1, 1, 1};
                }
                if (ImGui::IsItemHovered())
                    ImGui::SetTooltip("set: its own colour; unset: derived (see the help)");
                ImGui::SameLine();
                if (!v.hasColor) {
                    ImGui::TextDisabled("%s (derived)", label.c_str());
                    break;
                }
            }
            float c[3] = {v.color[0], v.color[1], v.color[2]};
            changed |= ImGui::ColorEdit3(label.c_str(), c,
                                         ImGuiColorEditFlags_HDR | ImGuiColorEditFlags_Float);
            for (int k = 0; k < 3; ++k)
                v.color[std::size_t(k)] = std::clamp(c[k], float(p.min), float(p.max));
            break;
        }
        case ParamType::Vector:
            ImGui::TextDisabled("%s: edit in JSON", label.c_str());
            break;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", paramTooltip(p, defaults).c_str());
    if (changed) p.set(owner, v);
    return changed;
}

//! Every parameter of `table` that applies (`applies`, Param::appliesTo bits).
template <class Owner>
bool paramTable(std::span<const Param<Owner>> table, Owner& owner, const Owner& defaults,
                std::uint32_t applies = ~0u) {
    bool changed = false;
    for (const Param<Owner>& p : table) {
        if (!(p.appliesTo & applies)) continue;
        ImGui::PushID(p.key.data());
        changed |= paramWidget(p, owner, defaults);
        ImGui::PopID();
    }
    return changed;
}

}  // namespace flarekit::studio

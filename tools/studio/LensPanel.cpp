// SPDX-License-Identifier: Apache-2.0
// The studio's lens mode: the cross-section, the picked ghost and its look, the iris, the
// coatings and surfaces, the render settings; and ghost picking on the view.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "App.h"
#include "ParamWidgets.h"
#include "flarekit/Lens.h"
#include "flarekit/ParamText.h"

namespace flarekit::studio {

Status App::pickGhost(Point at) {
    if (m_doc.kind != FlareKind::Lens) return invalidInput("pick: ghosts are picked in lens mode");
    if (!m_doc.hasImage()) return invalidInput("pick: no image is open");
    const LensJobOptions& job = m_doc.lensJob();
    auto lens = job.fNumber > 0 ? stopDown(m_doc.lens(), job.fNumber) : Result<Lens>(m_doc.lens());
    if (!lens) return lens.error();
    const Image& image = m_doc.source().image;
    auto ghosts =
        ghostsOnImage(*lens, image.width(), image.height(), m_doc.light, job.render.ghosts);
    if (!ghosts) return ghosts.error();
    m_picked.reset();
    // The ghost that shows there: of those whose disc holds the point, the brightest per area
    // (a small bright ghost over a large faint one); else the one whose edge is nearest.
    double best = 0;
    bool inside = false;
    for (const GhostOnImage& g : *ghosts) {
        const double d = std::hypot(g.x - at.x, g.y - at.y), r = std::max(g.radius, 1.0);
        const double brightness = (g.intensity[0] + g.intensity[1] + g.intensity[2]) / (r * r);
        if (d <= r) {
            if (!inside || brightness > best) m_picked = g, best = brightness, inside = true;
        } else if (!inside && (!m_picked || d - r < best)) {
            m_picked = g, best = d - r;
        }
    }
    if (!m_picked) return invalidInput("pick: this light draws no ghost");
    char line[200];
    std::snprintf(line, sizeof line,
                  "ghost of surfaces %d and %d (reflected at %d, then %d) at %.1f,%.1f, radius "
                  "%.1f px",
                  m_picked->first, m_picked->second, m_picked->first, m_picked->second, m_picked->x,
                  m_picked->y, m_picked->radius);
    say(line);
    if (!m_script.empty()) std::printf("picked %s\n", line);
    return Ok{};
}

void App::drawLensPanel() {
    // The cross-section with its direct and brightest ghost rays, made when the iris changes.
    const std::string key = m_doc.currentJson();
    if (key != m_diagramKey) {
        auto sheet = renderLensSheet(m_doc.lens(), 720);
        if (sheet) m_diagram.upload(toDisplay(std::move(*sheet), ToneOperator::None, 1.f));
        m_diagramKey = key;
    }
    const float w = ImGui::GetContentRegionAvail().x;
    if (m_diagram.valid())
        ImGui::Image(m_diagram.id(),
                     ImVec2(w, w * float(m_diagram.height()) / float(m_diagram.width())));
    ImGui::TextWrapped("%s: %zu surfaces. Right-click a ghost on the view to name its surfaces.",
                       m_doc.lens().name.c_str(), m_doc.lens().surfaces.size());
    ImGui::PushItemWidth(-150);
    if (m_picked) drawGhostLook();
    ImGui::Separator();
    ImGui::TextDisabled("iris");
    paramTable<LensAperture>(kLensApertureParams, m_doc.aperture(), LensAperture{});
    drawLensSurfaces();
    ImGui::Separator();
    ImGui::TextDisabled("stop and sources");
    for (const Param<LensJobOptions>& p : kLensJobParams) {
        if (p.key != "f_number" && p.key != "expand_highlights") continue;  // one placed light
        ImGui::PushID(p.key.data());
        paramWidget(p, m_doc.lensJob(), LensJobOptions{});
        ImGui::PopID();
    }
    ImGui::Separator();
    ImGui::TextDisabled("render");
    paramTable<LensRenderOptions>(kLensRenderParams, m_doc.lensJob().render, LensRenderOptions{});
    ImGui::PopItemWidth();
}

void App::drawGhostLook() {
    // The picked ghost's look (the lens file's ghost_pairs): its gain and tint over the trace.
    const int first = m_picked->first, second = m_picked->second;
    ImGui::TextColored(ImVec4(0.4f, 1.f, 0.8f, 1.f), "picked: the ghost of surfaces %d and %d",
                       first, second);
    GhostPairLook look = m_doc.ghostPair(first, second);
    const GhostPairLook defaults{first, second, 1.0, {1.f, 1.f, 1.f}};
    for (const Param<GhostPairLook>& p : kGhostPairParams) {
        ImGui::PushID(p.key.data());
        if (paramWidget(p, look, defaults)) {
            if (Status s = m_doc.setGhostPairParam(first, second, std::string(p.key), p.get(look));
                !s)
                say(s.error().message, true);
        }
        ImGui::PopID();
    }
}

void App::drawLensSurfaces() {
    // The prescription: the lens's coating on every glass-air surface, then each surface's
    // numbers, typed (a radius or thickness has no useful slider range) and applied when the
    // field is left; an edit the lens file would refuse is not applied and says why.
    ImGui::Separator();
    ImGui::TextDisabled("coatings and surfaces");
    static constexpr const char* kDesigns[] = {"none", "mgf2", "broadband"};
    static int design = 1;
    static double designNm = kMgF2DesignNm;
    ImGui::Combo("coating", &design, kDesigns, int(std::size(kDesigns)));
    ImGui::InputDouble("design nm", &designNm, 10, 50, "%.0f");
    if (ImGui::Button("coat every glass-air surface")) {
        if (Status s = m_doc.setLensCoating(-1, kDesigns[design], designNm); !s)
            say(s.error().message, true);
    }
    const Lens& lens = m_doc.lens();
    for (int i = 0; i < int(lens.surfaces.size()); ++i) {
        const LensSurface& surface = lens.surfaces[std::size_t(i)];
        ImGui::PushID(i);
        const std::string title =
            surface.stop
                ? "surface " + std::to_string(i) + ": the stop"
                : "surface " + std::to_string(i) + ": radius " + formatParamNumber(surface.radius) +
                      (surface.nd != 1.0 ? ", glass n_d " + formatParamNumber(surface.nd)
                                         : ", air") +
                      (surface.coating.layers.empty()
                           ? ", bare"
                           : ", " + std::to_string(surface.coating.layers.size()) +
                                 "-layer coating");
        if (ImGui::TreeNode(title.c_str())) {
            for (const Param<LensSurface>& p : kLensSurfaceParams) {
                if (p.type != ParamType::Number) continue;  // `stop` is the prescription's
                double v = p.get(surface).number;
                ImGui::InputDouble(std::string(p.key).c_str(), &v, 0, 0, "%.6g");
                if (ImGui::IsItemHovered())
                    ImGui::SetTooltip("%s", paramTooltip(p, LensSurface{}).c_str());
                if (ImGui::IsItemDeactivatedAfterEdit()) {
                    ParamValue value;
                    value.number = v;
                    if (Status s = m_doc.setLensSurfaceParam(i, std::string(p.key), value); !s)
                        say(s.error().message, true);
                }
            }
            if (!surface.stop && ImGui::Button("coat this surface")) {
                if (Status s = m_doc.setLensCoating(i, kDesigns[design], designNm); !s)
                    say(s.error().message, true);
            }
            ImGui::TreePop();
        }
        ImGui::PopID();
    }
}

}  // namespace flarekit::studio

// SPDX-License-Identifier: Apache-2.0
// The studio's panels: the menu, the preset (browser, element list, parameters), the view (the
// image, the light, the before/after split, the view settings, a sequence's timeline) and the
// component previews. The lens mode is LensPanel.cpp; the drive and scenes, GlViews.cpp.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "App.h"
#include "ParamWidgets.h"
#include "flarekit/Lens.h"

namespace flarekit::studio {

namespace {

constexpr float kPresetPanelWidth = 420.f;  //!< room for a slider, its value and its key
constexpr float kComponentsHeight = 200.f;  //!< a 16:9 preview 150 px tall and its label
constexpr float kThumbSize = 40.f;          //!< an element's thumbnail in the list
//! The view's margin around the image, a share of the view: the light can be dragged there,
//! outside the frame, as a sun just out of shot still throws its ghosts in.
constexpr float kViewMargin = 0.12f;

constexpr ImGuiWindowFlags kFixed = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                    ImGuiWindowFlags_NoCollapse |
                                    ImGuiWindowFlags_NoBringToFrontOnFocus;

//! A panel at a fixed place and size (the studio's layout is fixed, not dockable).
void beginPanel(const char* name, float x, float y, float w, float h,
                ImGuiWindowFlags flags = ImGuiWindowFlags_None) {
    ImGui::SetNextWindowPos(ImVec2(x, y));
    ImGui::SetNextWindowSize(ImVec2(w, h));
    ImGui::Begin(name, nullptr, kFixed | flags);
}

//! Flare files: flarekit and engine JSON, Unity assets, Godot scenes, Unreal settings.
const std::vector<std::string> kFlareExtensions = {".json", ".asset", ".tscn", ".ini"};
const std::vector<std::string> kImageExtensions = {".exr", ".hdr",  ".png",  ".jpg", ".jpeg",
                                                   ".tif", ".tiff", ".webp", ".bmp", ".tga"};

std::string elementLabel(const ElementParams& e, int i) {
    char text[96];
    std::snprintf(text, sizeof text, "%d  %s  t %.2f  size %.3f", i,
                  std::string(elementTypeName(e.type)).c_str(), double(e.t), double(e.size));
    return text;
}

}  // namespace

void App::drawPanels() {
    m_dragging = false;
    drawMenu();
    const ImGuiViewport* vp = ImGui::GetMainViewport();
    const float top = vp->WorkPos.y, width = vp->WorkSize.x, height = vp->WorkSize.y;
    drawPresetPanel(0, top, kPresetPanelWidth, height);
    drawViewPanel(kPresetPanelWidth, top, width - kPresetPanelWidth, height - kComponentsHeight);
    drawComponents(kPresetPanelWidth, top + height - kComponentsHeight, width - kPresetPanelWidth,
                   kComponentsHeight);
    drawQuestion();
    m_dialog.draw();
    m_dragging = m_dragging || ImGui::IsAnyItemActive();
}

void App::drawMenu() {
    if (!ImGui::BeginMainMenuBar()) return;
    if (ImGui::BeginMenu("File")) {
        if (ImGui::MenuItem("Open image...", "Ctrl+O"))
            m_dialog.open("Open image", kImageExtensions, false,
                          [this](const std::string& p) { openAny(p); });
        if (ImGui::MenuItem("Open sequence..."))
            m_dialog.open("Open sequence (any one of its frames)", kImageExtensions, false,
                          [this](const std::string& p) { openSequenceOf(p); });
        if (ImGui::MenuItem("Open scene..."))
            m_dialog.open("Open a Scene JSON (samples/scenes)", {".json"}, false,
                          [this](const std::string& p) {
                              if (Status st = openScene(p, "raycast"); !st)
                                  say(st.error().message, true);
                          });
        if (ImGui::MenuItem("Play the demo drive")) {
            DemoSettings settings;
            settings.width = kDriveWidth, settings.height = kDriveHeight;
            if (Status st = startDrive(settings); !st) say(st.error().message, true);
        }
        if (ImGui::MenuItem("Close the drive or scene", nullptr, false, m_drive || m_scene))
            m_drive.reset(), m_scene.reset();
        if (ImGui::MenuItem("Open preset..."))
            m_dialog.open("Open preset (flarekit, or an engine's flare)", kFlareExtensions, false,
                          [this](const std::string& p) { choosePreset(p); });
        if (ImGui::MenuItem("Save preset as...", "Ctrl+S"))
            m_dialog.open("Save preset (.json; .asset Unity, .tscn Godot, .ini Unreal)",
                          kFlareExtensions, true, [this](const std::string& p) { saveAs(p); });
        if (ImGui::MenuItem("Export render...", nullptr, false, m_doc.hasImage()))
            m_dialog.open("Export render (.exr float, .png 8-bit, .tif 16-bit)", kImageExtensions,
                          true, [this](const std::string& p) {
                              if (Status s = m_doc.exportRender(p); !s)
                                  return say(s.error().message, true);
                              say(std::string("exported ") + p);
                          });
        ImGui::Separator();
        if (ImGui::MenuItem("Quit")) glfwSetWindowShouldClose(m_window, GLFW_TRUE);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Edit")) {
        if (ImGui::MenuItem("Undo", "Ctrl+Z", false, m_doc.canUndo())) m_doc.undo();
        if (ImGui::MenuItem("Redo", "Ctrl+Shift+Z", false, m_doc.canRedo())) m_doc.redo();
        ImGui::EndMenu();
    }
    const std::string title =
        m_doc.presetName() + (m_doc.isDirty() ? " *" : "") + "   " + m_doc.imagePath();
    ImGui::TextDisabled("%s", title.c_str());
    ImGui::EndMainMenuBar();
}

void App::handleShortcuts() {
    const ImGuiIO& io = ImGui::GetIO();
    if (!io.KeyCtrl || io.WantTextInput) return;
    if (ImGui::IsKeyPressed(GLFW_KEY_Z, false)) io.KeyShift ? m_doc.redo() : m_doc.undo();
    if (ImGui::IsKeyPressed(GLFW_KEY_Y, false)) m_doc.redo();
    if (ImGui::IsKeyPressed(GLFW_KEY_O, false))
        m_dialog.open("Open image", kImageExtensions, false,
                      [this](const std::string& p) { openAny(p); });
    if (ImGui::IsKeyPressed(GLFW_KEY_S, false))
        m_dialog.open("Save preset (.json; .asset Unity, .tscn Godot, .ini Unreal)",
                      kFlareExtensions, true, [this](const std::string& p) { saveAs(p); });
}

void App::drawPresetPanel(float x, float y, float w, float h) {
    beginPanel("Preset", x, y, w, h);
    if (m_drive || m_scene) {
        m_drive ? drawDrivePanel() : drawScenePanel();
        ImGui::End();
        return;
    }
    int kind = int(m_doc.kind);
    ImGui::RadioButton("sprite (apply)", &kind, int(FlareKind::Sprite));
    ImGui::SameLine();
    ImGui::RadioButton("post-process (postfx)", &kind, int(FlareKind::PostFx));
    ImGui::SameLine();
    ImGui::RadioButton("lens", &kind, int(FlareKind::Lens));
    m_doc.kind = FlareKind(kind);
    if (ImGui::BeginCombo("preset", m_doc.presetName().c_str())) {
        for (const std::string& name : shipped())
            if (ImGui::Selectable(name.c_str())) choosePreset(name);
        ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("the shipped presets; unsaved edits are never dropped without asking");
    if (m_doc.kind == FlareKind::PostFx) {
        drawPostFxPanel();
        ImGui::End();
        return;
    }
    if (m_doc.kind == FlareKind::Lens) {
        drawLensPanel();
        ImGui::End();
        return;
    }
    paramTable<Preset>(kPresetParams, m_doc.preset(), Preset{});
    ImGui::Separator();
    drawElementList();
    ImGui::Separator();
    const int sel = m_doc.selected;
    if (sel >= 0 && sel < int(m_doc.preset().elements.size())) {
        ElementParams& e = m_doc.preset().elements[std::size_t(sel)];
        ImGui::Text("element %d: %s", sel, std::string(elementTypeName(e.type)).c_str());
        ImGui::PushItemWidth(-110);
        paramTable<ElementParams>(kElementParams, e, defaultElement(e.type), typeBit(e.type));
        ImGui::PopItemWidth();
    }
    ImGui::End();
}

void App::drawPostFxPanel() {
    PostFxParams& post = m_doc.postFx();
    ImGui::PushItemWidth(-130);
    paramTable<PostFxParams>(kPostFxTopParams, post, PostFxParams{});
    ImGui::BeginChild("sections");
    // One header per section of the preset, its keys from the section's table.
    forEachPostFxSection(post, [&](std::string_view name, auto table, auto& owner) {
        using Owner = std::decay_t<decltype(owner)>;
        const std::string label(name);
        if (!ImGui::CollapsingHeader(label.c_str(), name == "bright" || name == "bloom"
                                                        ? ImGuiTreeNodeFlags_DefaultOpen
                                                        : 0))
            return;
        ImGui::PushID(label.c_str());
        paramTable<Owner>(table, owner, Owner{});
        ImGui::PopID();
    });
    const std::string ghosts = "ghosts (" + std::to_string(post.ghosts.size()) + ")";
    if (ImGui::CollapsingHeader(ghosts.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) {
        int remove = -1;
        for (std::size_t i = 0; i < post.ghosts.size(); ++i) {
            GhostParams& g = post.ghosts[i];
            ImGui::PushID(int(i));
            char title[64];
            std::snprintf(title, sizeof title, "ghost %zu: scale %.3g", i, double(g.scale));
            const bool open = ImGui::TreeNode("ghost", "%s", title);
            ImGui::SameLine();
            if (ImGui::SmallButton("Remove")) remove = int(i);
            if (open) {
                paramTable<GhostParams>(kGhostParams, g, GhostParams{});
                ImGui::TreePop();
            }
            ImGui::PopID();
        }
        if (remove >= 0) m_doc.removeGhost(remove);
        if (ImGui::Button("Add ghost")) m_doc.addGhost();
    }
    ImGui::EndChild();
    ImGui::PopItemWidth();
}

void App::drawTimeline() {
    // The sequence's frames on disk, scrubbed by index (a gap in the numbers is no dead zone);
    // the arrow keys step a frame when the view has the focus.
    const std::vector<int>& frames = m_doc.frames();
    int index = int(std::lower_bound(frames.begin(), frames.end(), m_doc.frame()) - frames.begin());
    int wanted = index;
    ImGui::SameLine();
    ImGui::SetNextItemWidth(std::max(120.f, ImGui::GetContentRegionAvail().x - 220.f));
    ImGui::SliderInt("##frame", &wanted, 0, int(frames.size()) - 1,
                     ("frame " + std::to_string(frames[std::size_t(wanted)])).c_str());
    ImGui::SameLine();
    ImGui::TextDisabled("%zu frames%s", frames.size(),
                        m_doc.lightPlacedByHand ? ", light placed" : ", light found per frame");
    if (!ImGui::GetIO().WantTextInput) {
        if (ImGui::IsKeyPressed(ImGuiKey_RightArrow)) ++wanted;
        if (ImGui::IsKeyPressed(ImGuiKey_LeftArrow)) --wanted;
    }
    wanted = std::clamp(wanted, 0, int(frames.size()) - 1);
    if (wanted != index) {
        if (Status s = m_doc.showFrame(frames[std::size_t(wanted)]); !s)
            say(s.error().message, true);
    }
}

void App::drawElementList() {
    Preset& preset = m_doc.preset();
    const int n = int(preset.elements.size());
    ImGui::BeginChild("elements", ImVec2(0, std::min(360.f, 8.f + float(n) * (kThumbSize + 6.f))),
                      true);
    int moveFrom = -1, moveTo = -1;
    for (int i = 0; i < n; ++i) {
        ElementParams& e = preset.elements[std::size_t(i)];
        ImGui::PushID(i);
        ImGui::Image(thumbnail(e), ImVec2(kThumbSize, kThumbSize));
        ImGui::SameLine();
        bool visible = e.visible;
        if (ImGui::Checkbox("##visible", &visible)) m_doc.setVisible(i, visible);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("visible (saved in the preset)");
        ImGui::SameLine();
        const bool soloed = m_doc.solo == i;
        if (soloed) ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.8f, 0.5f, 0.1f, 1.f));
        if (ImGui::SmallButton("S")) m_doc.solo = soloed ? -1 : i;
        if (soloed) ImGui::PopStyleColor();
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("solo: this element alone (not saved)");
        ImGui::SameLine();
        if (ImGui::Selectable(elementLabel(e, i).c_str(), m_doc.selected == i, 0,
                              ImVec2(0, kThumbSize)))
            m_doc.selected = i;
        if (ImGui::BeginDragDropSource()) {  // drag a row onto another to reorder
            ImGui::SetDragDropPayload("element", &i, sizeof i);
            ImGui::Text("move %s", std::string(elementTypeName(e.type)).c_str());
            ImGui::EndDragDropSource();
        }
        if (ImGui::BeginDragDropTarget()) {
            if (const ImGuiPayload* p = ImGui::AcceptDragDropPayload("element"))
                moveFrom = *static_cast<const int*>(p->Data), moveTo = i;
            ImGui::EndDragDropTarget();
        }
        ImGui::PopID();
    }
    ImGui::EndChild();
    if (moveFrom >= 0) m_doc.moveElement(moveFrom, moveTo);
    const int sel = m_doc.selected;
    if (ImGui::Button("Up")) m_doc.moveElement(sel, sel - 1);
    ImGui::SameLine();
    if (ImGui::Button("Down")) m_doc.moveElement(sel, sel + 1);
    ImGui::SameLine();
    if (ImGui::Button("Duplicate")) m_doc.duplicateElement(sel);
    ImGui::SameLine();
    if (ImGui::Button("Remove") && n > 1) m_doc.removeElement(sel);
    ImGui::SameLine();
    if (ImGui::BeginCombo("##add", "Add", ImGuiComboFlags_NoArrowButton)) {
        // An image element needs a texture file: it comes from an engine's flare (File > Open
        // of a Unity, Babylon or three.js file), not from this list.
        for (int t = 0; t < kElementTypeCount; ++t)
            if (ElementType(t) != ElementType::Image &&
                ImGui::Selectable(std::string(elementTypeName(ElementType(t))).c_str()))
                m_doc.addElement(ElementType(t));
        ImGui::EndCombo();
    }
}

void App::drawViewPanel(float x, float y, float w, float h) {
    // No scroll bar: the canvas fills the panel exactly, and a bar appearing on the second frame
    // would change the preview's size under the user.
    beginPanel("View", x, y, w, h,
               ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
    ImGui::PushItemWidth(120);
    // A post-process flare comes from the image's own highlights: the light and its flux do
    // not apply (shown disabled, so that the view keeps its place).
    const bool postFx = m_doc.kind == FlareKind::PostFx;
    for (const Param<ViewSettings>& p : kViewParams) {
        const bool lightOnly = p.key == "flux_mode" || p.key == "intensity";
        ImGui::PushID(p.key.data());
        // The drive's frames are tone-mapped by its pipeline: no view setting applies to them.
        ImGui::BeginDisabled((postFx && lightOnly) || m_drive);
        paramWidget(p, m_doc.view, ViewSettings{});
        ImGui::EndDisabled();
        ImGui::PopID();
        ImGui::SameLine();
    }
    ImGui::SliderFloat("before | after", &m_split, 0.f, 1.f, "%.2f");
    ImGui::PopItemWidth();
    // The light typed in exactly (the pointer places it to the nearest screen pixel).
    float light[2] = {m_doc.light.x, m_doc.light.y};
    ImGui::SetNextItemWidth(200);
    ImGui::BeginDisabled(postFx || m_drive);
    if (ImGui::DragFloat2("light (image pixels)", light, 1.f, -1e5f, 1e5f, "%.1f"))
        m_doc.light = {light[0], light[1]}, m_doc.lightPlacedByHand = true;
    ImGui::EndDisabled();
    if (m_doc.isSequence()) drawTimeline();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(origin, ImVec2(origin.x + avail.x, origin.y + avail.y),
                        IM_COL32(30, 30, 34, 255));
    if (m_drive || m_scene) {
        m_drive ? drawDriveView(origin.x, origin.y, avail.x, avail.y)
                : drawSceneView(origin.x, origin.y, avail.x, avail.y);
        ImGui::End();
        return;
    }
    ImGui::InvisibleButton("canvas", ImVec2(std::max(avail.x, 1.f), std::max(avail.y, 1.f)));
    if (m_doc.hasImage()) {
        const Image& img = m_doc.source().image;
        const float margin = kViewMargin * std::min(avail.x, avail.y);
        const float fitW = avail.x - 2 * margin, fitH = avail.y - 2 * margin;
        const float k = std::min(fitW / float(img.width()), fitH / float(img.height()));
        m_view = {origin.x + 0.5f * (avail.x - k * float(img.width())),
                  origin.y + 0.5f * (avail.y - k * float(img.height())),
                  k * float(img.width()),
                  k * float(img.height()),
                  float(img.width()),
                  float(img.height())};
        m_viewMaxW = int(m_view.w), m_viewMaxH = int(m_view.h);
        if (m_doc.kind == FlareKind::Lens && ImGui::IsItemHovered() &&
            ImGui::IsMouseClicked(ImGuiMouseButton_Right)) {
            const ImVec2 m = ImGui::GetIO().MousePos;
            if (Status s = pickGhost(m_view.toImage(m.x, m.y)); !s) say(s.error().message, true);
        }
        if (!postFx && ImGui::IsItemActive() && ImGui::IsMouseDown(0)) {
            const ImVec2 m = ImGui::GetIO().MousePos;
            m_doc.light = m_view.toImage(m.x, m.y);
            m_doc.lightPlacedByHand = true;
            m_dragging = true;
        }
        const ImVec2 p0(m_view.x, m_view.y), p1(m_view.x + m_view.w, m_view.y + m_view.h);
        const float splitX = m_view.x + m_split * m_view.w;
        if (m_after.valid()) {
            if (m_split > 0 && m_before.valid())
                draw->AddImage(m_before.id(), p0, ImVec2(splitX, p1.y), ImVec2(0, 0),
                               ImVec2(m_split, 1));
            draw->AddImage(m_after.id(), ImVec2(splitX, p0.y), p1, ImVec2(m_split, 0),
                           ImVec2(1, 1));
            if (m_split > 0)
                draw->AddLine(ImVec2(splitX, p0.y), ImVec2(splitX, p1.y),
                              IM_COL32(255, 255, 255, 160));
        }
        draw->AddRect(p0, p1, IM_COL32(90, 90, 96, 255));
        float lx = 0, ly = 0;
        m_view.toWindow(m_doc.light, lx, ly);
        if (m_doc.kind == FlareKind::Lens && m_picked) {
            float gx = 0, gy = 0;
            m_view.toWindow({float(m_picked->x), float(m_picked->y)}, gx, gy);
            const float r = std::max(6.f, float(m_picked->radius) * m_view.w / m_view.imageW);
            draw->AddCircle(ImVec2(gx, gy), r, IM_COL32(90, 255, 200, 230), 48, 2.f);
            char label[48];
            std::snprintf(label, sizeof label, "%d-%d", m_picked->first, m_picked->second);
            draw->AddText(ImVec2(gx + r * 0.7f, gy - r * 0.7f - 14.f), IM_COL32(90, 255, 200, 255),
                          label);
        }
        if (!postFx) {
            draw->AddCircle(ImVec2(lx, ly), 9.f, IM_COL32(255, 220, 80, 230), 24, 1.5f);
            draw->AddLine(ImVec2(lx - 14, ly), ImVec2(lx + 14, ly), IM_COL32(255, 220, 80, 230));
            draw->AddLine(ImVec2(lx, ly - 14), ImVec2(lx, ly + 14), IM_COL32(255, 220, 80, 230));
        }
    } else {
        draw->AddText(ImVec2(origin.x + 20, origin.y + 20), IM_COL32(200, 200, 200, 255),
                      "File > Open image (or drop an image here) to design a flare on it");
    }
    ImGui::End();
}

void App::drawComponents(float x, float y, float w, float h) {
    beginPanel("Components", x, y, w, h,
               ImGuiWindowFlags_HorizontalScrollbar | ImGuiWindowFlags_NoTitleBar);
    // The tab a script asked for is selected once; after that the user's click decides.
    const auto tab = [&](const char* label, const char* name) {
        const bool asked = m_panelChanged && m_panel == name;
        if (!ImGui::BeginTabItem(label, nullptr, asked ? ImGuiTabItemFlags_SetSelected : 0)) return;
        if (!m_panelChanged) m_panel = name;
        ImGui::EndTabItem();
    };
    if (ImGui::BeginTabBar("strip")) {
        if (m_drive) {  // the drive's own strip: its frame's diagnostic views
            if (ImGui::BeginTabItem("Diagnostics")) ImGui::EndTabItem();
        } else {
            tab("Components", "components");
            tab("Presets", "presets");
        }
        ImGui::EndTabBar();
    }
    m_panelChanged = false;
    if (m_drive)
        drawDiagnosticStrip(h);
    else if (m_panel == "presets")
        drawBrowser(h);
    else
        drawComponentStrip(h);
    if (m_statusError) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.f, 0.45f, 0.4f, 1.f));
    // The backend that drew it: sprites are the CPU's whatever the view's setting.
    const bool gl = m_doc.view.backend == ViewBackend::Gl && m_doc.kind != FlareKind::Sprite;
    ImGui::Text("preview %dx%d, %.1f ms (%s)   %s", m_preview.width(), m_preview.height(),
                m_lastRenderMs, gl ? "gl" : "cpu", m_status.c_str());
    if (m_statusError) ImGui::PopStyleColor();
    ImGui::End();
}

float App::stripPictureHeight(float h) const {
    // Room below the pictures for the tabs, their names, the status line and the scroll bar.
    return h - 5.5f * ImGui::GetTextLineHeightWithSpacing() - ImGui::GetStyle().ScrollbarSize;
}

void App::drawComponentStrip(float h) {
    const float tall = stripPictureHeight(h);
    for (std::size_t i = 0; i < m_layerCount; ++i) {
        const auto& [name, texture] = m_layers[i];
        const float wide = tall * float(texture.width()) / float(std::max(1, texture.height()));
        ImGui::BeginGroup();
        ImGui::Image(texture.id(), ImVec2(wide, tall));
        ImGui::TextUnformatted(name.c_str());
        ImGui::EndGroup();
        ImGui::SameLine();
    }
    ImGui::NewLine();
}

void App::drawBrowser(float h) {
    const float tall = stripPictureHeight(h) - 6.f;  // the buttons' frame
    for (const std::string& name : shipped()) {
        ImGui::BeginGroup();
        ImGui::PushID(name.c_str());
        const auto it = m_presetThumbs.find(thumbId(m_doc.kind, name));
        const bool ready = it != m_presetThumbs.end();
        const float wide =
            ready ? tall * float(it->second.width()) / float(std::max(1, it->second.height()))
                  : tall * 16.f / 9.f;
        const auto error = m_presetErrors.find(thumbId(m_doc.kind, name));
        const bool clicked =
            ready ? ImGui::ImageButton(it->second.id(), ImVec2(wide, tall), ImVec2(0, 0),
                                       ImVec2(1, 1), 2)
                  : ImGui::Button(error != m_presetErrors.end() ? "cannot render" : "...",
                                  ImVec2(wide + 4, tall + 4));
        if (ImGui::IsItemHovered()) {
            const std::string tip = error != m_presetErrors.end()
                                        ? error->second
                                        : "load " + name + " (asks first when edits are unsaved)";
            ImGui::SetTooltip("%s", tip.c_str());
        }
        if (clicked) choosePreset(name);
        const bool current = name == m_doc.presetName();
        ImGui::TextColored(current ? ImVec4(1.f, 0.8f, 0.3f, 1.f) : ImVec4(0.9f, 0.9f, 0.9f, 1.f),
                           "%s", name.c_str());
        ImGui::PopID();
        ImGui::EndGroup();
        ImGui::SameLine();
    }
    ImGui::NewLine();
}

void App::drawQuestion() {
    if (m_pendingPreset && !ImGui::IsPopupOpen("Unsaved edits")) ImGui::OpenPopup("Unsaved edits");
    if (!ImGui::BeginPopupModal("Unsaved edits", nullptr, ImGuiWindowFlags_AlwaysAutoResize))
        return;
    if (!m_pendingPreset) {  // answered elsewhere (a script)
        ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
        return;
    }
    ImGui::Text("The preset \"%s\" has unsaved edits.", m_doc.presetName().c_str());
    ImGui::Text("Load %s and lose them?", m_pendingPreset->c_str());
    if (ImGui::Button("Save first...")) {
        const std::string next = *m_pendingPreset;
        m_pendingPreset.reset();
        ImGui::CloseCurrentPopup();
        m_dialog.open("Save preset", {".json"}, true, [this, next](const std::string& p) {
            if (Status s = m_doc.savePreset(p); !s) return say(s.error().message, true);
            choosePreset(next);
        });
    }
    ImGui::SameLine();
    if (ImGui::Button("Discard edits")) {
        const std::string next = *std::exchange(m_pendingPreset, std::nullopt);
        ImGui::CloseCurrentPopup();
        if (Status s = m_doc.loadPreset(next); !s) say(s.error().message, true);
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) {
        m_pendingPreset.reset();
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

}  // namespace flarekit::studio

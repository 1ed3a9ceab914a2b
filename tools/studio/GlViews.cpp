// SPDX-License-Identifier: Apache-2.0
// The studio's GL-rendered views: the demo drive (DrivePlayback) and a scene's still
// (ScenePlayback): their script actions, their panels (method, timeline, coverage graph, the
// sun) and their pictures in the view.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <vector>

#include "App.h"
#include "core/SafeWrite.h"
#include "flarekit/ImageIO.h"
#include "flarekit/Tonemap.h"
#include "flarekit/Visibility.h"

namespace flarekit::studio {

Status App::runDriveAction(const Action& a) {
    const auto fail = [&](const std::string& what) { return invalidInput(a.where + ": " + what); };
    if (a.kind == "drive") {
        DemoSettings settings;
        settings.width = kDriveWidth, settings.height = kDriveHeight;
        if (a.args.contains("method")) {
            if (!a.args["method"].is_string()) return fail("method: expected a method's name");
            settings.method = a.args["method"].get<std::string>();
        }
        if (a.args.contains("frames")) {
            auto frames = actionFrames(a, settings.frames);
            if (!frames) return frames.error();
            settings.frames = *frames;
        }
        if (Status s = startDrive(settings); !s) return fail(s.error().message);
        return Ok{};
    }
    if (!m_drive) return fail(a.kind + ": no drive is open (the \"drive\" action opens one)");
    if (a.kind == "frame") {
        const nlohmann::json& v = a.args["frame"];
        if (!v.is_number_integer() || v.get<long long>() < 1 ||
            v.get<long long>() > m_drive->ready())
            return fail("frame: expected a frame of the drive in [1, " +
                        std::to_string(m_drive->ready()) + "], got " + v.dump().substr(0, 40));
        m_driveFrame = int(v.get<long long>()) - 1;
        return Ok{};
    }
    if (a.kind == "diagnostics") {
        if (!a.args["dir"].is_string() || a.args["dir"].get<std::string>().empty())
            return fail("dir: expected a folder name");
        const DriveFrame shown = m_drive->frame(m_driveFrame);
        auto psp = pspDiagnosticsAt(shown.time);
        if (!psp) return fail(psp.error().message);
        return writeDiagnostics(a.args["dir"].get<std::string>(), shown.methodViews, *psp);
    }
    if (!a.args["path"].is_string()) return fail("path: expected a file name");
    const std::string path = a.args["path"].get<std::string>();
    if (a.kind == "coverage") return writeFileSafely(path, m_drive->coverageCsv());
    // export: the frame shown, as `flarekit demo` writes it.
    return writeImage8(path, m_drive->frame(m_driveFrame).image);
}

Status App::runSceneAction(const Action& a) {
    const auto fail = [&](const std::string& what) { return invalidInput(a.where + ": " + what); };
    if (a.kind == "scene") {
        if (!a.args["path"].is_string()) return fail("path: expected a Scene JSON file");
        std::string method = "raycast";
        if (a.args.contains("method")) {
            if (!a.args["method"].is_string()) return fail("method: expected a method's name");
            method = a.args["method"].get<std::string>();
        }
        if (Status s = openScene(a.args["path"].get<std::string>(), method); !s)
            return fail(s.error().message);
        return Ok{};
    }
    if (a.kind == "light") {
        auto at = actionPoint(a, "at");
        if (!at) return at.error();
        m_scene->aimSunAt(*at);
        return Ok{};
    }
    // export: the still, linear HDR to a float file or through the view's curve to 8/16-bit.
    if (!a.args["path"].is_string()) return fail("path: expected a file name");
    const std::string path = a.args["path"].get<std::string>();
    const std::optional<SceneFrame> still = m_scene->latest();
    if (!still) return fail("the scene's still is not made yet");
    std::printf("scene: sun direction %.9g,%.9g,%.9g at %.3f,%.3f, coverage %.5f\n",
                still->direction.x, still->direction.y, still->direction.z, double(still->sun.x),
                double(still->sun.y), still->coverage);
    std::fflush(stdout);
    Image out = still->hdr;
    if (!isFloatFormat(outputSampleFormat(path)))
        toneMapImage(out, m_doc.view.curve, m_doc.view.exposure);
    if (Status s = writeImage(path, out); !s) return fail(s.error().message);
    return Ok{};
}

Status App::openScene(const std::string& path, const std::string& method) {
    m_drive.reset(), m_scene.reset();
    auto scene = ScenePlayback::open(path, method, m_doc.preset());
    if (!scene) return scene.error();
    m_scene = std::move(*scene);
    m_sceneShown = 0;
    // As `flarekit render` writes 8-bit: ACES at exposure 1.
    m_doc.view.curve = ToneOperator::Aces, m_doc.view.exposure = 1.f;
    say("scene " + path);
    return Ok{};
}

Status App::startDrive(const DemoSettings& settings) {
    m_drive.reset(), m_scene.reset();  // the old worker stops first: one GL view at a time
    auto drive = DrivePlayback::start(settings, m_doc.preset());
    if (!drive) return drive.error();
    m_drive = std::move(*drive);
    m_driveFrame = 0, m_driveShown = -1, m_methodViewsShown = -1;
    say("drive: " + std::to_string(settings.frames) + " frames, " + settings.method);
    return Ok{};
}

void App::drawDrivePanel() {
    // The drive: its visibility method (switching renders it again), its frames so far, the
    // timeline, and the sun's coverage per frame, raw (the method's) and filtered (what the
    // flare weighs), with the frame shown marked.
    const DemoSettings& settings = m_drive->settings();
    ImGui::TextDisabled("the demo drive, %dx%d", settings.width, settings.height);
    static const std::vector<std::string> methods = [] {
        std::vector<std::string> names{"raycast"};
        for (const std::string& name : gpuVisibilityMethods()) names.push_back(name);
        return names;
    }();
    if (ImGui::BeginCombo("method", settings.method.c_str())) {
        for (const std::string& name : methods)
            if (ImGui::Selectable(name.c_str(), name == settings.method)) {
                DemoSettings next = settings;
                next.method = name;
                if (Status st = startDrive(next); !st) say(st.error().message, true);
                break;
            }
        ImGui::EndCombo();
    }
    if (!m_drive) return;
    if (const std::string e = m_drive->error(); !e.empty())
        ImGui::TextColored(ImVec4(1.f, 0.4f, 0.4f, 1.f), "%s", e.c_str());
    const int ready = m_drive->ready();
    ImGui::Text("%d of %d frames made", ready, m_drive->frameCount());
    if (ready == 0) return;
    int shown = std::clamp(m_driveFrame, 0, ready - 1) + 1;
    if (ImGui::SliderInt("frame", &shown, 1, ready)) m_driveFrame = shown - 1;
    std::vector<float> raw, filtered;
    m_drive->coverage(raw, filtered);
    const DriveFrame f = m_drive->frame(m_driveFrame = shown - 1);
    ImGui::Text("t %.2f s: coverage %.3f raw, %.3f filtered, %.2f of the disc in frame", f.time,
                f.rawCoverage, f.filteredCoverage, f.inFrame);
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const float w = ImGui::GetContentRegionAvail().x, h = 140.f;
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(at, ImVec2(at.x + w, at.y + h), IM_COL32(20, 20, 24, 255));
    const int total = m_drive->frameCount();
    const auto point = [&](int i, float v) {
        return ImVec2(at.x + w * (float(i) + 0.5f) / float(total), at.y + h * (1.f - v));
    };
    for (const auto& [series, colour] :
         {std::pair{&raw, IM_COL32(255, 170, 60, 255)}, {&filtered, IM_COL32(90, 200, 255, 255)}})
        for (int i = 1; i < int(series->size()); ++i)
            draw->AddLine(point(i - 1, (*series)[std::size_t(i - 1)]),
                          point(i, (*series)[std::size_t(i)]), colour, 1.5f);
    const float markX = point(m_driveFrame, 0).x;
    draw->AddLine(ImVec2(markX, at.y), ImVec2(markX, at.y + h), IM_COL32(255, 255, 255, 120));
    ImGui::Dummy(ImVec2(w, h));
    ImGui::TextColored(ImVec4(1.f, 0.67f, 0.24f, 1.f), "raw");
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(0.35f, 0.78f, 1.f, 1.f), "filtered (the flare's weight)");
}

void App::drawDriveView(float x, float y, float w, float h) {
    if (!m_drive || m_drive->ready() == 0) return;
    m_driveFrame = std::clamp(m_driveFrame, 0, m_drive->ready() - 1);
    if (m_driveShown != m_driveFrame) {
        m_driveTexture.upload(m_drive->frame(m_driveFrame).image);
        m_driveShown = m_driveFrame;
    }
    if (!ImGui::GetIO().WantTextInput) {
        if (ImGui::IsKeyPressed(ImGuiKey_RightArrow)) ++m_driveFrame;
        if (ImGui::IsKeyPressed(ImGuiKey_LeftArrow)) --m_driveFrame;
    }
    const float k = std::min(w / float(m_driveTexture.width()), h / float(m_driveTexture.height()));
    const float dw = k * float(m_driveTexture.width()), dh = k * float(m_driveTexture.height());
    const ImVec2 p0(x + 0.5f * (w - dw), y + 0.5f * (h - dh));
    ImGui::GetWindowDrawList()->AddImage(m_driveTexture.id(), p0, ImVec2(p0.x + dw, p0.y + dh));
}

void App::drawDiagnosticStrip(float h) {
    if (!m_drive || m_drive->ready() == 0) return;
    const int shown = std::clamp(m_driveFrame, 0, m_drive->ready() - 1);
    const DriveFrame frame = m_drive->frame(shown);
    const auto upload = [](std::vector<std::pair<std::string, GlTexture>>& textures,
                           const std::vector<DiagnosticPicture>& pictures) {
        textures.resize(pictures.size());
        for (std::size_t i = 0; i < pictures.size(); ++i) {
            textures[i].first = pictures[i].name;
            textures[i].second.upload(pictures[i].image, true);
        }
    };
    if (m_methodViewsShown != shown) {
        upload(m_methodViews, frame.methodViews);
        m_methodViewsShown = shown;
    }
    m_psp.request(shown, frame.time);
    if (const auto& made = m_psp.latest(); made && made->first != m_pspViewsShown) {
        m_pspViewsShown = made->first;
        if (!made->second) {
            m_pspViews.clear();
            m_pspSummary = "PSP: " + made->second.error().message;
        } else {
            const psp::PspFrameResult& r = made->second->result;
            upload(m_pspViews, made->second->pictures);
            char line[200];
            std::snprintf(line, sizeof line,
                          "PSP GE, frame %d: %d of %d mask pixels visible, coverage byte %d, flare "
                          "CLUT alpha %d",
                          made->first + 1, r.visiblePixels, r.maskPixels, r.coverageByte,
                          r.clutAlpha);
            m_pspSummary = r.sunInFrame ? line : "PSP GE: the sun is out of frame (no mask)";
        }
    }
    const float tall = stripPictureHeight(h) - ImGui::GetTextLineHeightWithSpacing();
    const float line = ImGui::GetTextLineHeightWithSpacing();
    const auto picture = [&](const std::string& name, const GlTexture& texture, float high) {
        ImGui::Image(
            texture.id(),
            ImVec2(high * float(texture.width()) / float(std::max(1, texture.height())), high));
        ImGui::TextUnformatted(name.c_str());
    };
    const auto pictures = [&](const std::vector<std::pair<std::string, GlTexture>>& textures) {
        for (std::size_t i = 0; i < textures.size(); ++i) {
            const auto& [name, texture] = textures[i];
            // The PSP's first and restored frames are the drive's frame again: in the files only.
            if (name == "01-scene" || name == "07-restored") continue;
            ImGui::BeginGroup();
            if (name == "08-clut-before" && i + 1 < textures.size()) {
                // The two CLUT strips (256 entries, 512x48) stacked: before, then after.
                const float half = 0.5f * (tall - line);
                picture(name, texture, half);
                ++i;
                picture(textures[i].first, textures[i].second, half);
            } else {
                picture(name, texture, tall);
            }
            ImGui::EndGroup();
            ImGui::SameLine();
        }
    };
    ImGui::Text("%s: %s   |   %s", m_drive->settings().method.c_str(),
                m_methodViews.empty()
                    ? "no working textures (raycast and the late methods keep none)"
                    : "its working textures for this frame",
                m_pspSummary.empty() ? "PSP GE: emulating..." : m_pspSummary.c_str());
    pictures(m_methodViews);
    if (!m_methodViews.empty()) ImGui::SameLine(0, 24.f);
    pictures(m_pspViews);
    ImGui::NewLine();
}

void App::drawScenePanel() {
    ImGui::TextWrapped("scene %s, %dx%d, method %s", m_scene->path().c_str(),
                       m_scene->scene().width, m_scene->scene().height, m_scene->method().c_str());
    if (const std::string e = m_scene->error(); !e.empty())
        ImGui::TextColored(ImVec4(1.f, 0.4f, 0.4f, 1.f), "%s", e.c_str());
    if (const auto still = m_scene->latest()) {
        ImGui::Text("sun at %.1f, %.1f: coverage %.4f", double(still->sun.x), double(still->sun.y),
                    still->coverage);
        ImGui::Text("direction %.4f, %.4f, %.4f", still->direction.x, still->direction.y,
                    still->direction.z);
    }
    ImGui::TextDisabled("drag on the view to move the sun; `flarekit render` draws the same still");
}

void App::drawSceneView(float x, float y, float w, float h) {
    ImGui::InvisibleButton("scene", ImVec2(std::max(w, 1.f), std::max(h, 1.f)));
    const std::optional<SceneFrame> still = m_scene->latest();
    if (!still) return;
    if (m_sceneShown != still->generation) {
        m_sceneTexture.upload(toDisplay(still->hdr, m_doc.view.curve, m_doc.view.exposure));
        m_sceneShown = still->generation;
    }
    const float k = std::min(w / float(still->hdr.width()), h / float(still->hdr.height()));
    m_sceneRect = {x + 0.5f * (w - k * float(still->hdr.width())),
                   y + 0.5f * (h - k * float(still->hdr.height())),
                   k * float(still->hdr.width()),
                   k * float(still->hdr.height()),
                   float(still->hdr.width()),
                   float(still->hdr.height())};
    if (ImGui::IsItemActive() && ImGui::IsMouseDown(0)) {
        const ImVec2 m = ImGui::GetIO().MousePos;
        m_scene->aimSunAt(m_sceneRect.toImage(m.x, m.y));
    }
    const ImVec2 p0(m_sceneRect.x, m_sceneRect.y);
    ImGui::GetWindowDrawList()->AddImage(m_sceneTexture.id(), p0,
                                         ImVec2(p0.x + m_sceneRect.w, p0.y + m_sceneRect.h));
}

}  // namespace flarekit::studio

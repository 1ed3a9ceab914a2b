// SPDX-License-Identifier: Apache-2.0
#include "App.h"

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "flarekit/ImageIO.h"
#include "flarekit/Lens.h"
#include "flarekit/Shot.h"

namespace flarekit::studio {

namespace {

//! Frames drawn before a plain --screenshot or a script's first action: Dear ImGui knows the
//! main menu's height (and so the panels' places) from the frame after it first sees it, so
//! the second frame is the settled layout; the third also has the preview of that view size.
constexpr int kSettleFrames = 3;
//! A drag's frames when the script gives none: enough to see the flare follow the pointer.
constexpr int kDefaultDragFrames = 8;

std::string g_glfwError;

void onGlfwError(int, const char* description) {
    g_glfwError = description ? description : "unknown error";
}

void onDrop(GLFWwindow* window, int count, const char** paths) {
    auto* app = static_cast<App*>(glfwGetWindowUserPointer(window));
    for (int i = 0; i < count; ++i) app->openAny(paths[i]);
}

//! A font with the characters the panels use, when the system has one; else ImGui's own.
void loadFont() {
    // DejaVu Sans ships in Debian's fonts-dejavu-core, which most desktops have.
    const char* path = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
    std::error_code ec;
    if (std::filesystem::exists(path, ec)) ImGui::GetIO().Fonts->AddFontFromFileTTF(path, 15.f);
}

}  // namespace

int runStudio(const StudioOptions& options) {
    const char* display = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    if ((!display || !*display) && (!wayland || !*wayland)) {
        std::fprintf(stderr,
                     "flarekit studio: needs a display (DISPLAY is not set); without one run it "
                     "under Xvfb: xvfb-run -a flarekit studio ...\n");
        return 2;
    }
    std::vector<Action> script;
    if (!options.script.empty()) {
        auto loaded = loadScript(options.script);
        if (!loaded) {
            std::fprintf(stderr, "flarekit studio: %s\n", loaded.error().message.c_str());
            return 2;
        }
        script = std::move(*loaded);
    }
    glfwSetErrorCallback(onGlfwError);
    if (!glfwInit()) {
        std::fprintf(stderr,
                     "flarekit studio: needs a display (%s: %s); without one run it under Xvfb: "
                     "xvfb-run -a flarekit studio ...\n",
                     display ? display : "", g_glfwError.c_str());
        return 2;
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    GLFWwindow* window =
        glfwCreateWindow(options.width, options.height, "flarekit studio", nullptr, nullptr);
    if (!window) {
        std::fprintf(stderr, "flarekit studio: no OpenGL 3.3 window on this display: %s\n",
                     g_glfwError.c_str());
        glfwTerminate();
        return 2;
    }
    glfwMakeContextCurrent(window);
    // Script and screenshot runs draw as fast as they can; a person's session follows the display.
    glfwSwapInterval(options.script.empty() && options.screenshot.empty() ? 1 : 0);
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the working folder
    ImGui::StyleColorsDark();
    loadFont();
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 330 core");
    int code = 0;
    {
        App app(window, options);
        glfwSetWindowUserPointer(window, &app);
        glfwSetDropCallback(window, onDrop);
        code = app.run();
    }
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window);
    glfwTerminate();
    return code;
}

App::App(GLFWwindow* window, const StudioOptions& options)
    : m_window(window),
      m_options(options),
      m_shipped{shippedPresetNames(), shippedPostFxPresetNames(), lensNames()} {
    if (!options.script.empty()) m_script = loadScript(options.script).value();
}

void App::openAny(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
    if (ext == ".json") {
        choosePreset(path);
        return;
    }
    if (Status s = m_doc.openImage(path); !s) return say(s.error().message, true);
    say(m_doc.isSequence() ? "opened " + path + ": " + std::to_string(m_doc.frames().size()) +
                                 " frames (" + describeFrames(m_doc.frames()) + ")"
                           : "opened " + path);
}

void App::openSequenceOf(const std::string& frameFile) {
    // The frame number is the last run of digits in the file's name: shot.1001.exr becomes
    // shot.####.exr, padded as the file is.
    const std::filesystem::path path(frameFile);
    const std::string stem = path.stem().string();
    const std::size_t end = stem.find_last_of("0123456789");
    if (end == std::string::npos)
        return say(frameFile + ": not a frame of a sequence (no frame number in its name)", true);
    std::size_t begin = end;
    while (begin > 0 && std::isdigit(static_cast<unsigned char>(stem[begin - 1]))) --begin;
    const std::string pattern = stem.substr(0, begin) + std::string(end + 1 - begin, '#') +
                                stem.substr(end + 1) + path.extension().string();
    openAny((path.parent_path() / pattern).string());
}

void App::say(const std::string& line, bool error) {
    m_status = line, m_statusError = error;
    if (error && !m_script.empty()) std::fprintf(stderr, "flarekit studio: %s\n", line.c_str());
}

int App::run() {
    if (!m_options.preset.empty()) {
        if (Status s = m_doc.loadPreset(m_options.preset); !s) {
            std::fprintf(stderr, "flarekit studio: %s\n", s.error().message.c_str());
            return 2;
        }
    }
    if (!m_options.file.empty()) {
        // A preset (flarekit's, or another engine's flare file) rather than an image.
        const std::string ext = std::filesystem::path(m_options.file).extension().string();
        const bool preset = ext == ".json" || ext == ".asset" || ext == ".tscn" || ext == ".ini";
        Status s = preset ? m_doc.loadPreset(m_options.file) : m_doc.openImage(m_options.file);
        if (!s) {
            std::fprintf(stderr, "flarekit studio: %s\n", s.error().message.c_str());
            return 2;
        }
    }
    while (m_exitCode < 0 && !glfwWindowShouldClose(m_window)) {
        if (!frame()) break;
    }
    if (m_options.stats && m_exitCode <= 0)
        std::fprintf(stderr,
                     "studio: %ld frames, %ld previews (%ld by gl), %.1f ms each on average; "
                     "drags %ld "
                     "frames at %.1f frames/s; longest frame beside the browser's work %.1f ms; "
                     "light at %.3f,%.3f\n",
                     m_frames, m_renders, m_glRenders,
                     m_renders ? m_renderMsTotal / double(m_renders) : 0.0, m_dragFrames,
                     m_dragSeconds > 0 ? double(m_dragFrames) / m_dragSeconds : 0.0,
                     m_longestBrowserFrame * 1000.0, double(m_doc.light.x), double(m_doc.light.y));
    return std::max(m_exitCode, 0);
}

bool App::frame() {
    // A frame's whole time while something is dragged, from one frame's start to the next's.
    const double now = glfwGetTime();
    if (m_dragging && m_frameStart > 0) m_dragSeconds += now - m_frameStart, ++m_dragFrames;
    m_frameStart = now;
    const long rendersBefore = m_renders;
    glfwPollEvents();
    if (Status s = stepScript(); !s) {
        std::fprintf(stderr, "flarekit studio: %s\n", s.error().message.c_str());
        m_exitCode = 2;
        return false;
    }
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    if (m_pointerScripted) {
        ImGuiIO& io = ImGui::GetIO();
        io.MousePos = ImVec2(m_pointerX, m_pointerY);
        io.MouseDown[0] = m_pointerDown;
    }
    ImGui::NewFrame();
    // One thumbnail per distinct element look: a slider's drag makes one per value, so they
    // are dropped now and then, between frames (a frame's draw lists name them).
    if (m_thumbs.size() > 256) m_thumbs.clear();
    drawPanels();
    handleShortcuts();
    if (!ImGui::IsAnyItemActive()) m_doc.commit();
    updatePreview();
    updateThumbnails();
    ImGui::Render();
    int fbw = 0, fbh = 0;
    glfwGetFramebufferSize(m_window, &fbw, &fbh);
    glViewport(0, 0, fbw, fbh);
    glClearColor(0.08f, 0.08f, 0.09f, 1.f);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    ++m_frames;
    std::string shot = std::exchange(m_pendingShot, "");
    if (shot.empty() && m_script.empty() && !m_options.screenshot.empty() &&
        m_frames == kSettleFrames)
        shot = m_options.screenshot;
    if (!shot.empty()) {
        if (Status s = writeScreenshot(shot); !s) {
            std::fprintf(stderr, "flarekit studio: %s\n", s.error().message.c_str());
            m_exitCode = 2;
            return false;
        }
        if (m_script.empty()) m_exitCode = 0;  // a plain --screenshot: one picture, then exit
    }
    glfwSwapBuffers(m_window);
    // The longest frame while the browser's thumbnails were being made and the view itself had
    // nothing to redraw: what the background work costs the window (uploads, contention).
    if (m_browser.busy() && m_renders == rendersBefore)
        m_longestBrowserFrame = std::max(m_longestBrowserFrame, glfwGetTime() - now);
    return true;
}

Status App::stepScript() {
    // The layout settles first (the main menu's height is known from the second frame on).
    if (m_script.empty() || m_frames < kSettleFrames) return Ok{};
    if (m_dragFrame >= 0) {  // a drag in progress: the pointer's next position
        const int frames = m_dragSteps;
        // Pressed from frame 0 to `frames` (k = 0 to 1), released on the frame after.
        const float k = std::min(1.f, float(m_dragFrame) / float(frames));
        const Point p{m_dragFrom.x + k * (m_dragTo.x - m_dragFrom.x),
                      m_dragFrom.y + k * (m_dragTo.y - m_dragFrom.y)};
        m_view.toWindow(p, m_pointerX, m_pointerY);
        m_pointerDown = m_dragFrame <= frames;
        if (m_dragFrame++ > frames) m_dragFrame = -1, m_pointerScripted = false;
        return Ok{};
    }
    if (m_waitFrames > 0) {
        --m_waitFrames;
        return Ok{};
    }
    // Each action waits for the view, its passes and the browser's thumbnails to show what the
    // actions before it made (a screenshot is then of a settled window).
    if (m_next > 0 && m_doc.hasImage() && !m_drive &&
        (!m_layersFresh || m_browser.busy() || m_browserKey.empty()))
        return Ok{};
    // A drive's actions wait for all its frames (its timeline and graph are then whole), a
    // scene's for the still of its newest sun.
    if (m_drive && !m_drive->finished()) return Ok{};
    // ... and for the diagnostic strip's PSP frame of the frame shown.
    if (m_drive && m_drive->ready() > 0 &&
        m_pspViewsShown != std::clamp(m_driveFrame, 0, m_drive->ready() - 1))
        return Ok{};
    if (m_scene && !m_scene->upToDate()) return Ok{};
    if (m_scene && !m_scene->error().empty()) return invalidInput("scene: " + m_scene->error());
    if (m_drive && !m_drive->error().empty()) return invalidInput("drive: " + m_drive->error());
    if (m_next >= m_script.size()) {
        // The last screenshot has been drawn and written; leave after it.
        if (m_pendingShot.empty()) m_exitCode = 0;
        return Ok{};
    }
    const Action& a = m_script[m_next++];
    if (a.kind == "scene" || (m_scene && (a.kind == "light" || a.kind == "export")))
        return runSceneAction(a);
    if (a.kind == "drive" || (m_drive && (a.kind == "frame" || a.kind == "export")) ||
        a.kind == "coverage" || a.kind == "diagnostics")
        return runDriveAction(a);
    if (a.kind == "open") m_drive.reset(), m_scene.reset();  // an image ends a drive or scene
    if (!isWindowAction(a.kind)) {
        Status s = runDocumentAction(m_doc, a);
        if (s) say(a.kind + " done");
        return s;
    }
    if (a.kind == "drag") {
        auto from = actionPoint(a, "from");
        if (!from) return from.error();
        auto to = actionPoint(a, "to");
        if (!to) return to.error();
        auto frames = actionFrames(a, kDefaultDragFrames);
        if (!frames) return frames.error();
        if (!m_doc.hasImage()) return invalidInput(a.where + ": drag: no image is open");
        m_dragFrom = *from, m_dragTo = *to, m_dragSteps = *frames;
        m_dragFrame = 0, m_pointerScripted = true;
        return stepScript();
    }
    if (a.kind == "pick") {
        auto at = actionPoint(a, "at");
        if (!at) return at.error();
        if (Status s = pickGhost(*at); !s) return invalidInput(a.where + ": " + s.error().message);
        return Ok{};
    }
    if (a.kind == "panel") {
        const std::string name =
            a.args["name"].is_string() ? a.args["name"].get<std::string>() : "";
        if (name != "components" && name != "presets")
            return invalidInput(a.where + ": name: expected \"components\" or \"presets\"");
        m_panel = name, m_panelChanged = true;
        return Ok{};
    }
    if (a.kind == "wait") {
        auto frames = actionFrames(a, 1);
        if (!frames) return frames.error();
        m_waitFrames = *frames - 1;
        return Ok{};
    }
    if (a.kind == "split") {
        if (!a.args["at"].is_number() || !(a.args["at"].get<double>() >= 0) ||
            a.args["at"].get<double>() > 1)
            return invalidInput(a.where + ": at: expected a number in [0, 1]");
        m_split = a.args["at"].get<float>();
        return Ok{};
    }
    if (a.kind == "choose") {
        if (!a.args["preset"].is_string())
            return invalidInput(a.where + ": preset: expected a preset name or file");
        choosePreset(a.args["preset"].get<std::string>());
        return Ok{};
    }
    if (a.kind == "answer") {
        const std::string choice =
            a.args["choice"].is_string() ? a.args["choice"].get<std::string>() : "";
        if (!m_pendingPreset) return invalidInput(a.where + ": answer: no question is open");
        if (choice == "discard") {
            const std::string name = *std::exchange(m_pendingPreset, std::nullopt);
            if (Status s = m_doc.loadPreset(name); !s)
                return invalidInput(a.where + ": " + s.error().message);
        } else if (choice == "cancel") {
            m_pendingPreset.reset();
        } else {
            return invalidInput(a.where + ": choice: expected \"discard\" or \"cancel\", got \"" +
                                choice + "\"");
        }
        return Ok{};
    }
    if (a.kind == "screenshot") {
        if (!a.args["path"].is_string())
            return invalidInput(a.where + ": path: expected a file name");
        m_pendingShot = a.args["path"].get<std::string>();
        if (Status s = checkOutputPath(m_pendingShot); !s)
            return invalidInput(a.where + ": " + s.error().message);
        return Ok{};
    }
    return Ok{};
}

void App::choosePreset(const std::string& name) {
    if (m_doc.isDirty()) {
        m_pendingPreset = name;  // drawQuestion asks before the edits are lost
        return;
    }
    if (Status s = m_doc.loadPreset(name); !s) return say(s.error().message, true);
    sayWithWarnings(std::string("preset ") + name);
}

void App::saveAs(const std::string& path) {
    if (Status s = m_doc.savePreset(path); !s) return say(s.error().message, true);
    sayWithWarnings(std::string("saved ") + path);
}

void App::sayWithWarnings(const std::string& line) {
    // What did not carry over between engines: the first on the status line, all on stderr.
    for (const std::string& w : m_doc.warnings)
        std::fprintf(stderr, "flarekit studio: %s\n", w.c_str());
    if (m_doc.warnings.empty()) return say(line);
    say(line + " (" + std::to_string(m_doc.warnings.size()) +
        " not carried over: " + m_doc.warnings.front() + ")");
}

void App::updatePreview() {
    if (!m_doc.hasImage() || m_viewMaxW <= 0 || m_viewMaxH <= 0) return;
    // While something is dragged, a preview slower than 30 frames/s is made at half the size,
    // and refined when the drag stops (full size, then the component passes).
    const bool coarse = m_dragging && m_lastRenderMs > 1000.0 / 30;
    m_preview.fit(m_doc, m_viewMaxW, m_viewMaxH, coarse ? 2 : 1);
    m_preview.dragging = m_dragging;
    char view[160];
    std::snprintf(view, sizeof view, "|%.3f,%.3f|%u|%d|%g|%d|%d|%g|%d", double(m_doc.light.x),
                  double(m_doc.light.y), m_doc.imageVersion(), m_preview.width(),
                  double(m_doc.view.exposure), int(m_doc.view.curve), int(m_doc.view.fluxMode),
                  double(m_doc.view.intensity), int(m_doc.view.backend));
    // A lens dragged is drawn with its brightest ghosts only: the key says so, so that the
    // whole flare is drawn when the drag stops.
    const bool lensDrag = m_doc.kind == FlareKind::Lens && m_dragging;
    const std::string key = (m_doc.kind == FlareKind::Sprite ? presetToJson(m_doc.renderedPreset())
                                                             : m_doc.currentJson()) +
                            view + (lensDrag ? "|coarse" : "");
    if (key != m_renderedKey) {
        auto frame = m_preview.render(m_doc);
        if (!frame) return say(frame.error().message, true);
        m_after.upload(frame->after);
        m_before.upload(m_preview.before(m_doc));
        m_renderedKey = key;
        m_lastRenderMs = frame->renderMs;
        ++m_renders;
        m_glRenders += m_doc.view.backend == ViewBackend::Gl && m_doc.kind != FlareKind::Sprite;
        m_renderMsTotal += frame->renderMs;
    }
    // The passes, once the drag stops (and only at full size: a coarse view is not final).
    const bool final = !m_dragging && !coarse;
    if (final && m_componentsKey != key) {
        auto parts = m_preview.renderComponents(m_doc);
        if (!parts) return say(parts.error().message, true);
        // Uploaded into the textures this frame's panels already name (deleting them now would
        // leave the frame's draw lists pointing at freed names).
        m_layers.resize(std::max(m_layers.size(), parts->layers.size()));
        for (std::size_t i = 0; i < parts->layers.size(); ++i) {
            m_layers[i].first = parts->layers[i].first;
            m_layers[i].second.upload(parts->layers[i].second);
        }
        m_layerCount = parts->layers.size();
        m_componentsKey = key;
    }
    m_layersFresh = final && m_componentsKey == m_renderedKey;
}

void App::updateThumbnails() {
    for (Thumbnail& t : m_browser.take()) {
        const std::string id = thumbId(m_browserKind, t.preset);
        if (t.image.pixels.empty()) {
            m_presetErrors[id] = t.error;
            continue;
        }
        m_presetErrors.erase(id);
        m_presetThumbs[id].upload(t.image);
    }
    if (!m_doc.hasImage() || m_dragging || m_preview.small().image.empty()) return;
    // Made again when the image, the light or the view changes, once it stops changing.
    char key[160];
    std::snprintf(key, sizeof key, "%d|%u|%.2f,%.2f|%g|%d|%d|%g", int(m_doc.kind),
                  m_doc.imageVersion(), double(m_doc.light.x), double(m_doc.light.y),
                  double(m_doc.view.exposure), int(m_doc.view.curve), int(m_doc.view.fluxMode),
                  double(m_doc.view.intensity));
    if (key == m_browserKey) return;
    m_browserKey = key;
    const double s = m_preview.smallScale();
    m_browserKind = m_doc.kind;
    m_browser.request(m_doc.kind, m_preview.small(),
                      {float(m_doc.light.x * s), float(m_doc.light.y * s)}, m_doc.view, shipped());
}

Status App::writeScreenshot(const std::string& path) {
    int w = 0, h = 0;
    glfwGetFramebufferSize(m_window, &w, &h);
    Image8 shot{w, h, 3, std::vector<std::uint8_t>(std::size_t(w) * std::size_t(h) * 3)};
    std::vector<std::uint8_t> rows(shot.pixels.size());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(GL_BACK);
    glReadPixels(0, 0, w, h, GL_RGB, GL_UNSIGNED_BYTE, rows.data());
    const std::size_t stride = std::size_t(w) * 3;
    for (int y = 0; y < h; ++y)  // GL's rows run bottom up
        std::copy_n(rows.data() + std::size_t(h - 1 - y) * stride, stride,
                    shot.pixels.data() + std::size_t(y) * stride);
    return writeImage8(path, shot);
}

ImTextureID App::thumbnail(const ElementParams& e) {
    ElementParams key = e;
    key.visible = true, key.intensity = 1.f;
    Preset one;
    one.elements = {key};
    const std::string id = presetToJson(one);
    auto it = m_thumbs.find(id);
    if (it == m_thumbs.end()) {
        it = m_thumbs.emplace(id, GlTexture{}).first;
        it->second.upload(elementThumbnail(e, 48));
    }
    return it->second.id();
}

}  // namespace flarekit::studio

// SPDX-License-Identifier: Apache-2.0
// The studio's window: GLFW 3.3 with an OpenGL 3.3 core context and Dear ImGui 1.86 panels
// over the Document, the CPU Preview uploaded to textures, and a script player that drives the
// same panels through the pointer.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "Document.h"
#include "DrivePlayback.h"
#include "FileDialog.h"
#include "GlTexture.h"
#include "Preview.h"
#include "ScenePlayback.h"
#include "Script.h"
#include "Thumbnails.h"

struct GLFWwindow;

namespace flarekit::studio {

struct StudioOptions {
    std::string file;        //!< an image or a preset JSON to open
    std::string preset;      //!< a preset to start with (name or file)
    std::string script;      //!< actions to play, then exit
    std::string screenshot;  //!< the whole window after the first frames (or the script)
    int width = 1600, height = 900;
    bool stats = false;  //!< frames and preview times on stderr at exit
};

//! Runs the studio; the process's exit code (0, or 2 for bad input or no display).
int runStudio(const StudioOptions& options);

//! Where the image sits in the view and how pointer positions map to image pixels.
struct ViewRect {
    float x = 0, y = 0, w = 0, h = 0;  //!< the image's rectangle in window pixels
    float imageW = 1, imageH = 1;      //!< the image's size in its own pixels
    Point toImage(float wx, float wy) const {
        return {(wx - x) / w * imageW, (wy - y) / h * imageH};
    }
    void toWindow(Point p, float& wx, float& wy) const {
        wx = x + p.x / imageW * w, wy = y + p.y / imageH * h;
    }
};

class App {
  public:
    App(GLFWwindow* window, const StudioOptions& options);
    //! The frame loop; the exit code.
    int run();
    //! A file dropped on the window or named on the command line: an image, or a preset.
    void openAny(const std::string& path);

  private:
    // One frame: script step, panels, preview, draw, screenshot.
    bool frame();
    Status stepScript();
    void drawPanels();
    void drawMenu();
    void drawPresetPanel(float x, float y, float w, float h);
    void drawElementList();
    void drawPostFxPanel();
    void drawLensPanel();
    void drawGhostLook();                               //!< the picked ghost's gain and tint
    void drawTimeline();                                //!< a sequence's frames, scrubbed
    void openSequenceOf(const std::string& frameFile);  //!< the sequence one frame is of
    // The demo drive (DrivePlayback): opened by the menu or the script's "drive" action; the
    // view shows its frame, the left panel its method, timeline and coverage graph.
    Status startDrive(const DemoSettings& settings);
    Status runDriveAction(const Action& a);
    void drawDriveView(float x, float y, float w, float h);
    void drawDrivePanel();
    //! The bottom strip while the drive plays: the shown frame's diagnostic views (Diagnostics.h).
    void drawDiagnosticStrip(float h);
    // A Scene JSON (ScenePlayback): opened by the script's "scene" action or `flarekit studio
    // scene.json`; the pointer aims its sun, the view shows its still.
    Status runSceneAction(const Action& a);
    Status openScene(const std::string& path, const std::string& method);
    void drawSceneView(float x, float y, float w, float h);
    void drawScenePanel();
    void drawLensSurfaces();  //!< the coatings and each surface's numbers
    //! Names the ghost nearest `at` (image pixels) among the lens's drawn ghosts: its pair of
    //! surfaces, shown on the view and in the status line (and on stdout for a script).
    Status pickGhost(Point at);
    void drawViewPanel(float x, float y, float w, float h);
    void drawComponents(float x, float y, float w, float h);
    void drawBrowser(float h);
    void drawComponentStrip(float h);
    float stripPictureHeight(float h) const;
    void updateThumbnails();
    void drawQuestion();
    void drawFileDialog();
    void handleShortcuts();
    void choosePreset(const std::string& name);
    //! Saves the preset (flarekit JSON, or an engine's format by extension) and says so.
    void saveAs(const std::string& path);
    //! `line` on the status line, with what the last load or save could not carry over.
    void sayWithWarnings(const std::string& line);
    void updatePreview();
    Status writeScreenshot(const std::string& path);
    void say(const std::string& line, bool error = false);
    ImTextureID thumbnail(const ElementParams& e);

    GLFWwindow* m_window;
    StudioOptions m_options;
    Document m_doc;
    Preview m_preview;
    GlTexture m_after, m_before;
    std::vector<std::pair<std::string, GlTexture>> m_layers;
    std::size_t m_layerCount = 0;  //!< the passes of the latest preview (m_layers may hold more)
    std::map<std::string, GlTexture> m_thumbs;
    // The preset browser: a thumbnail per shipped preset on this image, made in the background.
    ThumbnailRenderer m_browser;
    std::map<std::string, GlTexture> m_presetThumbs;
    std::map<std::string, std::string> m_presetErrors;
    std::string m_browserKey;
    std::string m_panel = "components";  //!< the bottom strip's tab: components or presets
    bool m_panelChanged = false;
    std::vector<std::string> m_shipped[3];  //!< the shipped presets (lenses) of each FlareKind
    const std::vector<std::string>& shipped() const { return m_shipped[int(m_doc.kind)]; }
    static std::string thumbId(FlareKind kind, const std::string& name) {
        return std::string(kFlareKindNames[int(kind)]) + "/" + name;
    }
    FlareKind m_browserKind = FlareKind::Sprite;  //!< of the thumbnails being made

    // What the shown preview was made from: a new render when any of it changes.
    std::string m_renderedKey, m_componentsKey;
    bool m_layersFresh = false;  //!< the view and the passes show the document as it is
    bool m_dragging = false;     //!< the light or a widget is being dragged this frame
    ViewRect m_view;
    int m_viewMaxW = 0, m_viewMaxH = 0;
    float m_split = 0.f;  //!< the before half's share of the view
    double m_lastRenderMs = 0;

    // A question that waits for an answer: the preset chosen while edits are unsaved.
    std::optional<std::string> m_pendingPreset;
    FileDialog m_dialog;

    // The script: its actions, where it is, a drag in progress, the exit code so far.
    std::vector<Action> m_script;
    std::size_t m_next = 0;
    int m_dragFrame = -1, m_waitFrames = 0;
    Point m_dragFrom, m_dragTo;  //!< the drag in progress, image pixels
    int m_dragSteps = 1;         //!< its frames
    bool m_pointerScripted = false;
    float m_pointerX = 0, m_pointerY = 0;
    bool m_pointerDown = false;
    std::string m_pendingShot;
    int m_exitCode = -1;  //!< set: leave the loop with it

    // The lens diagram (its cross-section, made when the lens or its iris changes) and the
    // ghost picked on the view.
    GlTexture m_diagram;
    std::string m_diagramKey;
    std::optional<GhostOnImage> m_picked;
    std::unique_ptr<DrivePlayback> m_drive;
    std::unique_ptr<ScenePlayback> m_scene;
    unsigned m_sceneShown = 0;  //!< the generation of the still uploaded
    GlTexture m_sceneTexture;
    ViewRect m_sceneRect;                     //!< where the still is drawn, for the pointer
    int m_driveFrame = 0, m_driveShown = -1;  //!< the frame on the timeline; the one uploaded
    GlTexture m_driveTexture;
    // The diagnostic strip: the method's views of the shown frame, the PSP's of the latest made.
    std::vector<std::pair<std::string, GlTexture>> m_methodViews, m_pspViews;
    int m_methodViewsShown = -1, m_pspViewsShown = -1;  //!< the drive frames uploaded
    std::string m_pspSummary;
    PspDiagnosticsWorker m_psp;
    //! The drive's size in the studio: a 16:9 preview (480x270 x 240 frames keeps 124 MiB).
    static constexpr int kDriveWidth = 480, kDriveHeight = 270;
    std::string m_status;
    bool m_statusError = false;
    long m_frames = 0, m_renders = 0, m_glRenders = 0, m_dragFrames = 0;
    double m_frameStart = 0, m_dragSeconds = 0, m_longestBrowserFrame = 0;
    double m_renderMsTotal = 0;
};

}  // namespace flarekit::studio

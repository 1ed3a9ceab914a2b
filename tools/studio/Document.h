// SPDX-License-Identifier: Apache-2.0
// What the studio edits: an image, a sprite preset and where the light is, with undo and redo
// for every change to the preset and a record of what was last saved. No GL and no UI here, so
// the script, the benchmark and the tests drive the same model the panels do.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "flarekit/Convert.h"
#include "flarekit/Flare.h"
#include "flarekit/PostFxParams.h"
#include "flarekit/Result.h"
#include "flarekit/job/ApplyJob.h"
#include "flarekit/job/LensJob.h"
#include "flarekit/job/PixelJob.h"
#include "flarekit/job/PostFxJob.h"

namespace flarekit::studio {

//! Which flare the studio shows and edits: a sprite preset (`flarekit apply`) or a post-process
//! preset (`flarekit postfx`). Both are kept; switching is not an edit.
enum class FlareKind { Sprite, PostFx, Lens };
inline constexpr std::string_view kFlareKindNames[] = {"sprite", "postfx", "lens"};

//! Where the view and the exports draw a post-process preset or a lens (GlViewBackends.h).
enum class ViewBackend { Cpu, Gl };
inline constexpr std::string_view kViewBackendNames[] = {"cpu", "gl"};

//! How the image is shown (and how 8/16-bit exports are encoded); not part of the preset.
struct ViewSettings {
    float exposure = 1.f;                     //!< multiplies the image before the curve
    ToneOperator curve = ToneOperator::None;  //!< set from the image on open
    FluxMode fluxMode = FluxMode::Fixed;      //!< the preset's own look while designing
    float intensity = 1.f;                    //!< the job's flare brightness multiplier
    ViewBackend backend = ViewBackend::Cpu;
};
inline constexpr Param<ViewSettings> kViewParams[] = {
    param<&ViewSettings::exposure>("exposure", 0, 1000, "",
                                   "multiplies the image before the display curve"),
    choice<&ViewSettings::curve>("tonemap", kToneOperatorNames,
                                 "display curve: none, aces or filmic (HDR images open with "
                                 "filmic, as the CLI writes them to 8/16-bit files)"),
    choice<&ViewSettings::fluxMode>("flux_mode", kFluxModeNames,
                                    "fixed: the preset's own strength wherever the light is; "
                                    "measured: as bright as the image is at the light"),
    param<&ViewSettings::intensity>("intensity", 0, 1000, "", "flare brightness multiplier"),
    choice<&ViewSettings::backend>(
        "backend", kViewBackendNames,
        "where the view and the exports draw post-process presets and lenses: cpu, or gl "
        "(flarekit's OpenGL backend, as --backend gl, in a context the studio keeps); sprite "
        "presets are drawn on the CPU either way"),
};

//! The postfx job's options for `preset` on a display (the view, a thumbnail, an 8/16-bit file):
//! the preset's curve, else the view's (filmic for HDR by default, as the CLI writes an 8-bit
//! file), and the view's exposure on top of the preset's.
PostFxJobOptions postFxDisplayOptions(const PostFxParams& preset, const ViewSettings& view,
                                      const std::string& name);

class Document {
  public:
    Document();

    //! Reads an image as `flarekit apply` does and places the light on the brightest light
    //! the finder accepts (else two thirds across, a quarter down). The preset is kept.
    Status openImage(const std::string& path);
    //! A shipped preset of the current kind by name or a JSON file, replacing that preset
    //! (undoable). Another engine's flare file (a Unity .asset, a Godot .tscn, Unreal settings,
    //! a PlayCanvas, Babylon.js or three.js JSON) is read through flarekit convert's importer and
    //! switches to its kind (sprite or post-process); what did not map is in `warnings`.
    //! Callers ask first when isDirty().
    Status loadPreset(const std::string& nameOrPath);
    //! The current kind's preset as the CLI reads it (presetToJson, postFxPresetToJson), written
    //! atomically; clears isDirty(). An engine's file (by extension: .asset, .tscn, .ini, or the
    //! JSON of the engine the preset was opened from, at its own path) is written by flarekit
    //! convert's exporter, with its textures beside it.
    Status savePreset(const std::string& path);
    //! What the last load or save could not carry over (one line each), for the status line.
    std::vector<std::string> warnings;
    FlareKind kind = FlareKind::Sprite;
    //! The current kind's preset name, and the shipped presets of that kind.
    std::string presetName() const;
    std::vector<std::string> shippedNames() const;
    //! The flare at the image's full size, in `depth` (Auto: float for EXR, the extension's
    //! default otherwise). Float and half files get linear values (no exposure or curve), 8/16-bit
    //! files the view's exposure and curve, as the CLI writes them.
    Status exportRender(const std::string& path, SampleFormat depth = SampleFormat::Auto) const;

    // Edits of the preset. Each is one undo step; a slider's drag is one step however many
    // values it passes (commit() closes it).
    Preset& preset() { return m_preset; }
    const Preset& preset() const { return m_preset; }
    Status setElementParam(int element, const std::string& key, const ParamValue& value);
    Status setPresetParam(const std::string& key, const ParamValue& value);
    // The post-process preset's edits: a section's key (bloom.levels), a ghost's, a top key.
    PostFxParams& postFx() { return m_post; }
    const PostFxParams& postFx() const { return m_post; }
    Status setPostFxParam(const std::string& section, const std::string& key,
                          const ParamValue& value);
    Status setGhostParam(int ghost, const std::string& key, const ParamValue& value);
    void addGhost();  //!< a copy of the last ghost (or a default one), at the end
    void removeGhost(int ghost);
    // The lens: a prescription (its surfaces, glasses and coatings), its iris, a look per
    // ghost, and the f-number and render settings of `flarekit lens render` (flags, not saved).
    const Lens& lens() const { return m_lens; }
    LensAperture& aperture() { return m_lens.aperture; }
    //! Sets a parameter of surface `surface` (radius, thickness, n_d, v_d, semi_aperture);
    //! refused, the lens unchanged, when the lens would be refused as a file.
    Status setLensSurfaceParam(int surface, const std::string& key, const ParamValue& value);
    //! Puts a coating ("none", "mgf2", "broadband", or a design at `designNm`) on surface
    //! `surface`, or with surface -1 on every glass-air surface (the lens's own coating).
    Status setLensCoating(int surface, const std::string& design, double designNm);
    //! Sets gain or tint of the ghost of surfaces (first, second), adding its look when new.
    Status setGhostPairParam(int first, int second, const std::string& key,
                             const ParamValue& value);
    //! The look of the ghost of surfaces (first, second) (gain 1, white when it has none).
    GhostPairLook ghostPair(int first, int second) const;
    LensJobOptions& lensJob() { return m_lensJob; }
    const LensJobOptions& lensJob() const { return m_lensJob; }
    //! The lens job's options: the lens in memory, the light at `scale` x the document's;
    //! `coarse`: the few brightest ghosts on coarse meshes, for a drag.
    LensJobOptions lensOptions(double scale, bool coarse) const;
    void addElement(ElementType type);  //!< after the selection, selected
    void duplicateElement(int element);
    void removeElement(int element);  //!< the last element cannot go (a preset needs one)
    void moveElement(int element, int to);
    void setVisible(int element, bool visible);
    //! Records the edits made since the last commit as one undo step (nothing when the preset
    //! is as it was). The UI calls it when no widget is being dragged.
    void commit();
    bool undo();
    bool redo();
    bool canUndo() const { return !m_undo.empty() || changedSinceCommit(); }
    bool canRedo() const { return !m_redo.empty(); }
    //! The current kind's preset differs from the last one saved or loaded.
    bool isDirty() const;
    //! The current kind's preset as text (a lens: its name and settings): what isDirty compares.
    std::string currentJson() const;

    //! What is drawn: the preset with the soloed element alone, when one is.
    Preset renderedPreset() const;
    int solo = -1;     //!< an element shown alone (a view state: not saved, not undone)
    int selected = 0;  //!< the element the parameter panel edits

    // The image and the light.
    bool hasImage() const { return !m_source.image.empty(); }
    // An image sequence (a pattern such as shot.####.exr or shot.%04d.exr, as the CLI reads
    // one): its frames on disk and the one shown. A single image has none.
    bool isSequence() const { return !m_frames.empty(); }
    const std::vector<int>& frames() const { return m_frames; }
    int frame() const { return m_frame; }
    const std::string& sequencePattern() const { return m_sequence; }
    //! Shows frame `frame` (a frame number on disk) of the sequence. The light moves to that
    //! frame's own light, as `--light auto` finds it, unless it was placed by hand.
    Status showFrame(int frame);
    bool lightPlacedByHand = false;  //!< set by a drag or a typed light; a new image clears it
    const PixelInput& source() const { return m_source; }
    const std::string& imagePath() const { return m_imagePath; }
    //! Changes each time an image is opened (previews made from the old one are stale).
    unsigned imageVersion() const { return m_imageVersion; }
    const std::string& presetPath() const { return m_presetPath[int(kind)]; }
    Point light{0, 0};
    ViewSettings view;
    //! The apply job's options for this document (light, flux, view) at `scale` x the image.
    ApplyOptions applyOptions(double scale, const std::string& output = "") const;
    //! The postfx job's options: the preset in memory, and for a display (an 8/16-bit file or
    //! the view) the view's curve when the preset has none and its exposure on the preset's.
    PostFxJobOptions postFxOptions(bool display) const;
    //! Starts the GL backends the first time the view asks for them (view.backend); after
    //! that, postFxOptions and lensOptions draw through them. The error names the setting.
    Status prepareBackend() const;

  private:
    mutable std::shared_ptr<const PostFxBackend> m_glPostFx;  //!< made by prepareBackend
    mutable std::shared_ptr<const LensBackend> m_glLens;
    Status saveLens(const std::string& path);  //!< the lens as its JSON file (savePreset)
    //! Both presets: what an undo step restores.
    struct Design {
        Preset sprite;
        PostFxParams post;
        Lens lens;
        LensJobOptions lensJob;
    };
    Design design() const { return {m_preset, m_post, m_lens, m_lensJob}; }
    void restore(const Design& d);
    //! The current design as text: what an edit is detected by (against m_committedText).
    std::string designText() const;
    //! The current design becomes the one undo steps start from.
    void markCommitted();
    bool changedSinceCommit() const;
    void clampSelection();
    //! Reads `path` as the image shown; `fresh`: a new image (its view curve, its light).
    Status loadImageFile(const std::string& path, bool fresh);
    PixelInput m_source;
    std::string m_sequence;     //!< the pattern, when a sequence is open
    std::vector<int> m_frames;  //!< its frames on disk, ascending
    int m_frame = 0;
    unsigned m_imageVersion = 0;
    std::string m_imagePath;
    Preset m_preset;
    PostFxParams m_post;
    Lens m_lens;
    LensJobOptions m_lensJob;
    Design m_committed;
    std::string m_committedText;  //!< designText() of m_committed, kept, not remade each frame
    std::string m_presetPath[3], m_savedJson[3];  //!< per FlareKind
    //! After a preset replaced the current kind's: one undo step back to `before`, and `path`
    //! as what is saved and unchanged.
    void finishLoad(const Design& before, const std::string& path);
    //! The engine format each kind's preset was opened from (Flarekit: a preset file or name).
    FlareFormat m_format[3] = {FlareFormat::Flarekit, FlareFormat::Flarekit, FlareFormat::Flarekit};
    std::vector<Design> m_undo, m_redo;
};

}  // namespace flarekit::studio

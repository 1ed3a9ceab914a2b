// SPDX-License-Identifier: Apache-2.0
#include "Document.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "GlViewBackends.h"
#include "core/ParamJson.h"
#include "core/SafeWrite.h"
#include "flarekit/ImageIO.h"
#include "flarekit/Shot.h"
#include "flarekit/Tonemap.h"
#include "flarekit/job/Job.h"
#include "flarekit/job/PixelJob.h"

namespace flarekit::studio {

namespace {

//! Where the light goes when the image has none the finder accepts: up and to the right of the
//! centre, so that the flare's elements spread across the frame as a sun's would.
constexpr double kFallbackLightX = 2.0 / 3.0, kFallbackLightY = 0.25;

template <class Owner>
Status setByKey(std::span<const Param<Owner>> table, Owner& owner, const std::string& key,
                const ParamValue& value, std::uint32_t applies, const std::string& where) {
    const Param<Owner>* p = findParam(table, key);
    if (!p || !(p->appliesTo & applies)) return invalidInput(where + key + ": unknown parameter");
    p->set(owner, value);
    return Ok{};
}

}  // namespace

Document::Document() {
    auto preset = flarekit::loadPreset(kDefaultSpritePreset);
    if (preset) {
        m_preset = *preset;
        m_presetPath[0] = kDefaultSpritePreset;
    } else {  // no shipped presets found: one glow, so that there is something to edit
        m_preset.name = "untitled";
        m_preset.elements.push_back(defaultElement(ElementType::Glow));
    }
    auto post = loadPostFxPreset(kDefaultPostFxPreset);
    if (post) {
        m_post = *post;
        m_presetPath[1] = kDefaultPostFxPreset;
    }
    // The first shipped lens, so that the lens mode has one to show.
    for (const std::string& name : lensNames()) {
        auto lens = loadLens(name);
        if (!lens) continue;
        m_lens = *lens;
        m_presetPath[2] = m_lensJob.lens = name;
        break;
    }
    markCommitted();
    m_savedJson[0] = presetToJson(m_preset);
    m_savedJson[1] = postFxPresetToJson(m_post);
}

namespace {

//! A lens setting's text for undo and change checks: the lens as its file (surfaces, coatings,
//! iris, ghost looks), then the job's flags that differ from their defaults.
std::string lensText(const Lens& lens, const LensJobOptions& job) {
    return lensToJson(lens) + job.lens +
           writeParams<LensJobOptions>(job, kLensJobParams, LensJobOptions{}).dump() +
           writeParams<LensRenderOptions>(job.render, kLensRenderParams, LensRenderOptions{})
               .dump();
}

}  // namespace

std::string Document::designText() const {
    return presetToJson(m_preset) + postFxPresetToJson(m_post) + lensText(m_lens, m_lensJob);
}

void Document::markCommitted() {
    m_committed = design();
    m_committedText = designText();
}

std::string Document::currentJson() const {
    if (kind == FlareKind::Lens) return lensText(m_lens, m_lensJob);
    return kind == FlareKind::Sprite ? presetToJson(m_preset) : postFxPresetToJson(m_post);
}

void Document::restore(const Design& d) {
    m_preset = d.sprite;
    m_post = d.post;
    m_lens = d.lens;
    m_lensJob = d.lensJob;
    markCommitted();
    clampSelection();
}

std::string Document::presetName() const {
    if (kind == FlareKind::Lens) return m_lensJob.lens;
    return kind == FlareKind::Sprite ? m_preset.name : m_post.name;
}

std::vector<std::string> Document::shippedNames() const {
    if (kind == FlareKind::Lens) return lensNames();
    return kind == FlareKind::Sprite ? shippedPresetNames() : shippedPostFxPresetNames();
}

LensJobOptions Document::lensOptions(double scale, bool coarse) const {
    LensJobOptions o = m_lensJob;
    o.lensData = std::make_shared<const Lens>(m_lens);
    o.lightMode = LensLightMode::At;
    o.light = Point{float(light.x * scale), float(light.y * scale)};
    o.tonemap = ToneOperator::None;
    if (view.backend == ViewBackend::Gl && m_glLens) o.backend = m_glLens;
    if (coarse) {
        // A drag's preview: the eight brightest ghosts on 16-ray meshes, the starburst at three
        // wavelengths (about a tenth of the full render); refined when the drag stops.
        o.render.ghosts = std::min(o.render.ghosts, 8);
        o.render.gridSide = std::min(o.render.gridSide, 16);
        o.render.starburstSamples = 3;
    }
    return o;
}

Status Document::openImage(const std::string& path) {
    if (!isFramePattern(path)) {
        if (Status s = loadImageFile(path, true); !s) return s;
        m_sequence.clear(), m_frames.clear();
        return Ok{};
    }
    auto pattern = parseFramePattern(path);
    if (!pattern) return pattern.error();
    std::vector<int> frames = framesOnDisk(*pattern);
    if (frames.empty())
        return invalidInput(path +
                            ": no frame of the sequence is on disk (expected files such as " +
                            pattern->path(1001) + ")");
    if (Status s = loadImageFile(pattern->path(frames.front()), true); !s) return s;
    m_sequence = path, m_frames = std::move(frames), m_frame = m_frames.front();
    return Ok{};
}

Status Document::showFrame(int frame) {
    if (!std::binary_search(m_frames.begin(), m_frames.end(), frame))
        return invalidInput("frame " + std::to_string(frame) + ": not on disk (the sequence has " +
                            describeFrames(m_frames) + ")");
    auto pattern = parseFramePattern(m_sequence);
    if (!pattern) return pattern.error();
    const Point kept = light;
    if (Status s = loadImageFile(pattern->path(frame), false); !s) return s;
    if (lightPlacedByHand) light = kept;
    m_frame = frame;
    return Ok{};
}

Status Document::loadImageFile(const std::string& path, bool fresh) {
    auto loaded = readImage(path);
    if (!loaded) return loaded.error();
    m_source = PixelInput{std::move(loaded->image), !loaded->wasFloat, loaded->hasAlpha, path};
    m_imagePath = path;
    ++m_imageVersion;
    if (fresh) {
        // As the CLI writes this image to an 8/16-bit file: filmic for HDR data, none for 8-bit.
        view.curve = defaultDisplayCurve(loaded->wasFloat, "view.png");
        view.exposure = 1.f;
        lightPlacedByHand = false;
    }
    const LightSearch found = findLights(m_source.image);
    if (!found.lights.empty()) {
        light = found.lights.front().position;
    } else {
        light = {float(kFallbackLightX * m_source.image.width()),
                 float(kFallbackLightY * m_source.image.height())};
    }
    return Ok{};
}

namespace {
//! The engine format of a file the studio is asked to open, or Flarekit (a shipped name, a
//! flarekit preset, or a file no importer recognises: the preset reader's message then says why).
FlareFormat formatOfFile(const std::string& nameOrPath) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(nameOrPath, ec)) return FlareFormat::Flarekit;
    auto format = detectFlareFormat(nameOrPath);
    return format ? *format : FlareFormat::Flarekit;
}
}  // namespace

Status Document::loadPreset(const std::string& nameOrPath) {
    commit();
    const Design before = design();
    warnings.clear();
    if (const FlareFormat format = formatOfFile(nameOrPath); format != FlareFormat::Flarekit) {
        auto asset = importFlare(nameOrPath);
        if (!asset) return asset.error();
        kind = asset->postFx ? FlareKind::PostFx : FlareKind::Sprite;
        if (asset->postFx) {
            m_post = asset->chain;
        } else {
            m_preset = asset->sprite;
            solo = -1;
        }
        warnings = asset->warnings;
        m_format[int(kind)] = format;
        finishLoad(before, nameOrPath);
        return Ok{};
    }
    m_format[int(kind)] = FlareFormat::Flarekit;
    if (kind == FlareKind::Sprite) {
        auto preset = flarekit::loadPreset(nameOrPath);
        if (!preset) return preset.error();
        m_preset = *preset;
        solo = -1;
    } else if (kind == FlareKind::PostFx) {
        auto post = loadPostFxPreset(nameOrPath);
        if (!post) return post.error();
        m_post = *post;
    } else {
        auto lens = loadLens(nameOrPath);
        if (!lens) return lens.error();
        m_lens = *lens;
        m_lensJob.lens = nameOrPath;
    }
    finishLoad(before, nameOrPath);
    return Ok{};
}

void Document::finishLoad(const Design& before, const std::string& path) {
    m_undo.push_back(before);
    m_redo.clear();
    markCommitted();
    m_savedJson[int(kind)] = currentJson();
    m_presetPath[int(kind)] = path;
    clampSelection();
}

Status Document::savePreset(const std::string& path) {
    commit();
    if (kind == FlareKind::Lens) return saveLens(path);
    // Never a file the CLI would refuse: the edits are checked as the reader checks them.
    const Status valid =
        kind == FlareKind::Sprite ? validatePreset(m_preset) : validatePostFxParams(m_post);
    if (!valid) return invalidInput(path + ": not saved: " + valid.error().message);
    const std::string text = currentJson();
    warnings.clear();
    // An engine's file: by its extension, or the JSON of the engine the preset came from when
    // saved back to where it was opened.
    ConvertOptions options;
    auto byExtension = outputFlareFormat(path, options);
    const bool sameFile = path == m_presetPath[int(kind)];
    const FlareFormat format =
        byExtension ? *byExtension : (sameFile ? m_format[int(kind)] : FlareFormat::Flarekit);
    if (format == FlareFormat::Flarekit) {
        if (Status s = writeFileSafely(path, text); !s) return s;
    } else {
        FlareAsset asset;
        asset.postFx = kind == FlareKind::PostFx;
        asset.sprite = m_preset;
        asset.chain = m_post;
        auto written = exportFlare(asset, path, format, options);
        if (!written) return written.error();
        warnings = *written;
    }
    m_format[int(kind)] = format;
    m_savedJson[int(kind)] = text;
    m_presetPath[int(kind)] = path;
    return Ok{};
}

ApplyOptions Document::applyOptions(double scale, const std::string& output) const {
    ApplyOptions o;
    o.preset = m_presetPath[0].empty() ? "preset" : m_presetPath[0];
    o.output = output;
    o.light = Point{float(light.x * scale), float(light.y * scale)};
    o.fluxMode = view.fluxMode;
    o.intensity = view.intensity;
    o.exposure = view.exposure;
    o.tonemap = view.curve;
    return o;
}

PostFxJobOptions postFxDisplayOptions(const PostFxParams& preset, const ViewSettings& view,
                                      const std::string& name) {
    PostFxJobOptions o;
    o.preset = name;
    o.presetParams = std::make_shared<const PostFxParams>(preset);
    o.tonemap = preset.tone.op != ToneOperator::None ? preset.tone.op : view.curve;
    o.exposure = preset.tone.exposure * view.exposure;
    return o;
}

PostFxJobOptions Document::postFxOptions(bool display) const {
    const std::string name = m_presetPath[1].empty() ? "postfx preset" : m_presetPath[1];
    PostFxJobOptions o;
    if (display) {
        o = postFxDisplayOptions(m_post, view, name);
    } else {
        o.preset = name;
        o.presetParams = std::make_shared<const PostFxParams>(m_post);
    }
    if (view.backend == ViewBackend::Gl && m_glPostFx) o.backend = m_glPostFx;
    return o;
}

Status Document::prepareBackend() const {
    if (view.backend != ViewBackend::Gl || m_glPostFx) return Ok{};
    auto thread = GlViewThread::start();
    if (!thread) return invalidInput("backend gl: " + thread.error().message);
    m_glPostFx = glViewPostFxBackend(*thread);
    m_glLens = glViewLensBackend(*thread);
    return Ok{};
}

Status Document::exportRender(const std::string& path, SampleFormat depth) const {
    if (!hasImage()) return invalidInput(path + ": no image is open to render");
    if (Status s = prepareBackend(); !s) return s;
    // An EXR export is the render at full float precision unless a depth is asked for.
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
    if (depth == SampleFormat::Auto && ext == ".exr") depth = SampleFormat::Float;
    if (Status s = checkSampleFormatFits(path, depth); !s) return s;
    const bool display = !isFloatFormat(outputSampleFormat(path, depth));
    if (Status s = checkOutputPath(path); !s) return s;
    Result<PixelOutput> out = invalidInput("");
    if (kind == FlareKind::Sprite) {
        ApplyOptions o = applyOptions(1.0, path);
        if (!display) o.exposure = 1.f, o.tonemap = ToneOperator::None;
        out = applyPixels(o, renderedPreset(), m_source);
    } else if (kind == FlareKind::PostFx) {
        out = postFxPixels(postFxOptions(display), m_source);
    } else {
        // Linear from the job; a display file through the view's exposure and curve (the
        // CLI's lens render has no exposure: equal to it at the view's default of 1).
        out = lensPixels(lensOptions(1.0, false), m_source);
        if (out && display) toneMapImage(out->image, view.curve, view.exposure);
    }
    if (!out) return out.error();
    WriteOptions w;
    w.alpha = m_source.hasAlpha;
    w.format = depth;
    return writeImage(path, out->image, w);
}

Status Document::setElementParam(int element, const std::string& key, const ParamValue& value) {
    if (element < 0 || element >= int(m_preset.elements.size()))
        return invalidInput(std::string("element ") + std::to_string(element) +
                            ": the preset has " + std::to_string(m_preset.elements.size()) +
                            " elements");
    ElementParams& e = m_preset.elements[std::size_t(element)];
    return setByKey<ElementParams>(kElementParams, e, key, value, typeBit(e.type),
                                   "elements[" + std::to_string(element) + "].");
}

Status Document::setPresetParam(const std::string& key, const ParamValue& value) {
    return setByKey<Preset>(kPresetParams, m_preset, key, value, ~0u, "");
}

Status Document::setPostFxParam(const std::string& section, const std::string& key,
                                const ParamValue& value) {
    if (section.empty())
        return setByKey<PostFxParams>(kPostFxTopParams, m_post, key, value, ~0u, "");
    Status status = invalidInput(section +
                                 ": unknown section (expected one of: bright, bloom, "
                                 "halo, streaks, chromatic, starburst, dirt, tonemap)");
    forEachPostFxSection(m_post, [&](std::string_view name, auto table, auto& owner) {
        using Owner = std::decay_t<decltype(owner)>;
        if (name == section) status = setByKey<Owner>(table, owner, key, value, ~0u, section + ".");
    });
    return status;
}

Status Document::saveLens(const std::string& path) {
    // A lens file is flarekit's own JSON; no engine holds a prescription.
    if (std::filesystem::path(path).extension() != ".json")
        return invalidInput(path +
                            ": not saved: a lens is saved as .json (the format of "
                            "docs/lens.md); no engine format holds a prescription");
    if (Status s = validateLens(m_lens, path); !s)
        return invalidInput(path + ": not saved: " + s.error().message);
    if (Status s = writeFileSafely(path, lensToJson(m_lens)); !s) return s;
    warnings = {
        "saved the prescription, iris and ghost looks; the f-number and render settings "
        "are `flarekit lens render` flags"};
    m_savedJson[int(kind)] = currentJson();
    m_presetPath[int(kind)] = path;
    return Ok{};
}

Status Document::setLensSurfaceParam(int surface, const std::string& key, const ParamValue& value) {
    if (surface < 0 || surface >= int(m_lens.surfaces.size()))
        return invalidInput("surface " + std::to_string(surface) + ": the lens has " +
                            std::to_string(m_lens.surfaces.size()) + " surfaces");
    Lens edited = m_lens;
    if (Status s =
            setByKey<LensSurface>(kLensSurfaceParams, edited.surfaces[std::size_t(surface)], key,
                                  value, ~0u, "surfaces[" + std::to_string(surface) + "].");
        !s)
        return s;
    if (Status s = validateLens(edited, m_lens.name); !s) return s;
    m_lens = std::move(edited);
    return Ok{};
}

Status Document::setLensCoating(int surface, const std::string& design, double designNm) {
    LensCoating coating;
    if (design != "none") {
        int index = -1;
        for (std::size_t i = 0; i < std::size(kCoatingDesignNames); ++i)
            if (kCoatingDesignNames[i] == design) index = int(i);
        if (index < 0)
            return invalidInput("coating: expected \"none\", \"mgf2\" or \"broadband\", got \"" +
                                design + "\"");
        if (!(designNm >= 380 && designNm <= 780))
            return invalidInput("design_nm: expected a wavelength in [380, 780] nm");
        coating = coatingDesign(CoatingDesign(index), designNm);
    }
    Lens edited = m_lens;
    if (surface < 0) {
        edited.coating = coating;
        for (std::size_t i = 0; i < edited.surfaces.size(); ++i)
            if (takesLensCoating(edited, i)) edited.surfaces[i].coating = coating;
    } else if (surface < int(edited.surfaces.size())) {
        edited.surfaces[std::size_t(surface)].coating = coating;
    } else {
        return invalidInput("surface " + std::to_string(surface) + ": the lens has " +
                            std::to_string(m_lens.surfaces.size()) + " surfaces");
    }
    if (Status s = validateLens(edited, m_lens.name); !s) return s;
    m_lens = std::move(edited);
    return Ok{};
}

GhostPairLook Document::ghostPair(int first, int second) const {
    for (const GhostPairLook& g : m_lens.ghostPairs)
        if (g.first == first && g.second == second) return g;
    return {first, second, 1.0, {1.f, 1.f, 1.f}};
}

Status Document::setGhostPairParam(int first, int second, const std::string& key,
                                   const ParamValue& value) {
    Lens edited = m_lens;
    auto it = std::find_if(
        edited.ghostPairs.begin(), edited.ghostPairs.end(),
        [&](const GhostPairLook& g) { return g.first == first && g.second == second; });
    if (it == edited.ghostPairs.end()) {
        edited.ghostPairs.push_back(ghostPair(first, second));
        it = edited.ghostPairs.end() - 1;
    }
    if (Status s = setByKey<GhostPairLook>(
            kGhostPairParams, *it, key, value, ~0u,
            "ghost_pairs[" + std::to_string(first) + ", " + std::to_string(second) + "].");
        !s)
        return s;
    if (Status s = validateLens(edited, m_lens.name); !s) return s;
    m_lens = std::move(edited);
    return Ok{};
}

Status Document::setGhostParam(int ghost, const std::string& key, const ParamValue& value) {
    if (ghost < 0 || ghost >= int(m_post.ghosts.size()))
        return invalidInput("ghost " + std::to_string(ghost) + ": the preset has " +
                            std::to_string(m_post.ghosts.size()) + " ghosts");
    return setByKey<GhostParams>(kGhostParams, m_post.ghosts[std::size_t(ghost)], key, value, ~0u,
                                 "ghosts[" + std::to_string(ghost) + "].");
}

void Document::addGhost() {
    if (m_post.ghosts.size() >= std::size_t(kMaxGhosts)) return;
    m_post.ghosts.push_back(m_post.ghosts.empty() ? GhostParams{} : m_post.ghosts.back());
    commit();
}

void Document::removeGhost(int ghost) {
    if (ghost < 0 || ghost >= int(m_post.ghosts.size())) return;
    m_post.ghosts.erase(m_post.ghosts.begin() + ghost);
    commit();
}

void Document::addElement(ElementType type) {
    const auto at =
        m_preset.elements.begin() +
        std::clamp<std::ptrdiff_t>(selected + 1, 0, std::ptrdiff_t(m_preset.elements.size()));
    selected = int(at - m_preset.elements.begin());
    m_preset.elements.insert(at, defaultElement(type));
    commit();
}

void Document::duplicateElement(int element) {
    if (element < 0 || element >= int(m_preset.elements.size())) return;
    const ElementParams copy = m_preset.elements[std::size_t(element)];
    m_preset.elements.insert(m_preset.elements.begin() + element + 1, copy);
    selected = element + 1;
    commit();
}

void Document::removeElement(int element) {
    if (m_preset.elements.size() <= 1 || element < 0 || element >= int(m_preset.elements.size()))
        return;
    m_preset.elements.erase(m_preset.elements.begin() + element);
    if (solo == element) solo = -1;
    if (solo > element) --solo;
    clampSelection();
    commit();
}

void Document::moveElement(int element, int to) {
    const int n = int(m_preset.elements.size());
    if (element < 0 || element >= n) return;
    to = std::clamp(to, 0, n - 1);
    if (to == element) return;
    const ElementParams moved = m_preset.elements[std::size_t(element)];
    m_preset.elements.erase(m_preset.elements.begin() + element);
    m_preset.elements.insert(m_preset.elements.begin() + to, moved);
    if (selected == element) selected = to;
    if (solo == element) solo = to;
    commit();
}

void Document::setVisible(int element, bool visible) {
    if (element < 0 || element >= int(m_preset.elements.size())) return;
    m_preset.elements[std::size_t(element)].visible = visible;
    commit();
}

bool Document::changedSinceCommit() const {
    return designText() != m_committedText;
}

void Document::commit() {
    if (!changedSinceCommit()) return;
    m_undo.push_back(m_committed);
    m_redo.clear();
    markCommitted();
}

bool Document::undo() {
    commit();
    if (m_undo.empty()) return false;
    m_redo.push_back(design());
    restore(m_undo.back());
    m_undo.pop_back();
    return true;
}

bool Document::redo() {
    if (m_redo.empty()) return false;
    m_undo.push_back(design());
    restore(m_redo.back());
    m_redo.pop_back();
    return true;
}

bool Document::isDirty() const {
    return currentJson() != m_savedJson[int(kind)];
}

Preset Document::renderedPreset() const {
    Preset p = m_preset;
    if (solo >= 0 && solo < int(p.elements.size()))
        for (int i = 0; i < int(p.elements.size()); ++i)
            p.elements[std::size_t(i)].visible = i == solo;
    return p;
}

void Document::clampSelection() {
    const int n = int(m_preset.elements.size());
    selected = std::clamp(selected, 0, std::max(0, n - 1));
    if (solo >= n) solo = -1;
}

}  // namespace flarekit::studio

// SPDX-License-Identifier: Apache-2.0
#include "HostFlare.h"

namespace flarekit::host {

namespace {

//! The flare a job added to `plate`, times `gain`: what intensity means for the post-process
//! chain and the lens, whose jobs have no multiplier of their own (1 leaves the job's image).
void scaleFlare(Image& result, const Image& plate, float gain) {
    if (gain == 1.f) return;
    float* r = result.data();
    const float* p = plate.data();
    for (std::size_t i = 0; i < 4 * result.pixelCount(); i += 4)
        for (std::size_t c = 0; c < 3; ++c) r[i + c] = p[i + c] + gain * (r[i + c] - p[i + c]);
}

}  // namespace

std::string lookName(FlareMode mode, const std::string& name) {
    if (!name.empty()) return name;
    switch (mode) {
        case FlareMode::PostFx:
            return kDefaultPostFxPreset;
        case FlareMode::Lens:
            return kDefaultHostLens;
        case FlareMode::Sprite:
            break;
    }
    return kDefaultSpritePreset;
}

std::vector<std::string> lookNames(FlareMode mode) {
    switch (mode) {
        case FlareMode::PostFx:
            return shippedPostFxPresetNames();
        case FlareMode::Lens:
            return lensNames();
        case FlareMode::Sprite:
            break;
    }
    return shippedPresetNames();
}

Result<Look> Look::load(FlareMode mode, const std::string& name) {
    Look look;
    look.mode = mode;
    look.name = lookName(mode, name);
    switch (mode) {
        case FlareMode::Sprite: {
            auto preset = loadPreset(look.name);
            if (!preset) return preset.error();
            look.preset = std::move(*preset);
            break;
        }
        case FlareMode::PostFx: {
            auto params = loadPostFxPreset(look.name);
            if (!params) return params.error();
            look.postFx = std::make_shared<const PostFxParams>(std::move(*params));
            break;
        }
        case FlareMode::Lens: {
            auto lens = loadLens(look.name);
            if (!lens) return lens.error();
            look.lens = std::make_shared<const Lens>(std::move(*lens));
            break;
        }
    }
    return look;
}

LightSearchOptions searchOptions(const FlareRequest& request) {
    LightSearchOptions search = request.search;
    if (request.threshold > 0) search.minLuminance = float(request.threshold);
    return search;
}

namespace {

Result<PixelOutput> spriteFlare(const Look& look, const FlareRequest& r, PixelInput input) {
    ApplyOptions o;
    o.preset = look.name;
    o.intensity = r.intensity;
    o.lightSearch = searchOptions(r);
    o.light = r.light;
    if (r.light && r.lightScale) {
        // A tracked light's strength, as a tracked shot in `flarekit apply` has it.
        o.fluxMode = FluxMode::Fixed;
        o.intensity *= *r.lightScale;
    }
    return applyPixels(o, *look.preset, std::move(input));
}

Result<PixelOutput> postFxFlare(const Look& look, const FlareRequest& r, PixelInput input) {
    PostFxJobOptions o;
    o.preset = look.name;
    o.presetParams = look.postFx;
    if (r.threshold > 0) o.threshold = float(r.threshold);
    // Display-referred pixels clip their lights at white: without their highlights expanded
    // (as `flarekit postfx --expand-highlights` does) the chain's bright-pass sees no light.
    if (input.displayReferred) o.expandHighlights = ExpandHighlights{}.gain;
    return postFxPixels(o, std::move(input));
}

Result<PixelOutput> lensFlare(const Look& look, const FlareRequest& r, PixelInput input) {
    LensJobOptions o;
    o.lens = look.name;
    o.lensData = look.lens;
    if (r.threshold > 0) o.threshold = r.threshold;
    if (r.light) o.lightMode = LensLightMode::At, o.light = *r.light;
    return lensPixels(o, std::move(input));
}

}  // namespace

Result<Image> drawFlare(const Look& look, const FlareRequest& r, PixelInput input) {
    if (look.mode == FlareMode::Sprite) {
        auto out = spriteFlare(look, r, std::move(input));
        if (!out) return out.error();
        return std::move(out->image);
    }
    const Image plate = input.image;
    auto out = look.mode == FlareMode::PostFx ? postFxFlare(look, r, std::move(input))
                                              : lensFlare(look, r, std::move(input));
    if (!out) return out.error();
    scaleFlare(out->image, plate, r.intensity);
    return std::move(out->image);
}

}  // namespace flarekit::host

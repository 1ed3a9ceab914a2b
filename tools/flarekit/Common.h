// SPDX-License-Identifier: Apache-2.0
// What every subcommand shares: turning library errors into one stderr line and an exit code
// (0 success, 2 bad input, 1 internal failure), warnings, and small argument parsers.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdio>
#include <functional>
#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

#include "core/SafeWrite.h"  // makeOutputDirectory, shared by every subcommand
#include "flarekit/Flare.h"
#include "flarekit/ImageIO.h"
#include "flarekit/PostFxParams.h"
#include "flarekit/Result.h"
#if FLAREKIT_HAS_GL
#include "flarekit/gl/HeadlessGl.h"
#endif

namespace flarekit::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitInternal = 1;
inline constexpr int kExitBadInput = 2;

//! Prints "flarekit: <message>" (one line, capped) and returns the exit code for the error:
//! 1 internal, 128 + signal for an interrupt, 2 otherwise.
int report(const Error& error);
//! The process's exit code once the subcommand returned `exitCode`: an interrupt that arrived
//! (even after the work was done) gives 128 + signal and one line saying so; a write error on
//! standard output turns success into exit 2.
int finishProcess(int exitCode);
//! The first line of `message`, cut to 1,000 characters.
std::string cappedLine(const std::string& message);
//! The first line of `text`, cut to `max` characters.
std::string excerptLine(const std::string& text, std::size_t max);
void warn(const std::string& message);

//! Holds back what libraries print on stderr while it lives; on destruction replays it except
//! the lines starting with one of `dropped` (by default libpng's own "libpng error: ..." lines,
//! which repeat what flarekit reports in its one line). Filters alive at once on several threads
//! share one capture, replayed when the last ends (its first dropped line goes to that one).
class LibraryNoiseFilter {
  public:
    explicit LibraryNoiseFilter(std::vector<std::string> dropped = {"libpng "});
    ~LibraryNoiseFilter();
    LibraryNoiseFilter(const LibraryNoiseFilter&) = delete;
    LibraryNoiseFilter& operator=(const LibraryNoiseFilter&) = delete;
    //! Stops capturing now (replaying what was kept); the first dropped line, trimmed.
    std::string finish();

  private:
    std::vector<std::string> m_dropped;
    std::string m_firstDropped;
    bool m_active = false;
};

//! readImage8 with library noise filtered.
inline Result<Image8> readImage8Quietly(const std::string& path) {
    LibraryNoiseFilter filter;
    return readImage8(path);
}

//! The presets a subcommand uses when --preset is not given.
inline constexpr const char* kDefaultSpritePreset = "tanczos-classic";
inline constexpr const char* kDefaultPostFxPreset = "photo";

//! The --tonemap choices: `extra` (a command's own words, such as "auto" or "preset") and then the
//! curves' names as kToneOperatorNames types them, so a curve's name is written once.
std::vector<std::string> toneChoices(std::initializer_list<const char*> extra);

//! The curve a `--tonemap` value names (one of kToneOperatorNames), or nothing for a command's
//! own default word (`auto`, `preset`).
std::optional<ToneOperator> namedToneOperator(const std::string& name);

//! The default display curve of HDR data: HDR (float) input written to an 8/16-bit file goes
//! through Hable's filmic curve, which rolls a sun of 30,000 and its flare off into white over
//! several stops instead of clipping everything above 1 to a flat disc; its toe keeps the
//! shadows of the photograph. Float outputs stay linear and unclamped, and 8-bit input is
//! already display-referred: none.
ToneOperator defaultDisplayCurve(bool hdrInput, const std::string& out,
                                 SampleFormat requested = SampleFormat::Auto);
//! A rendered frame's curve (render, lights): `--tonemap NAME` for 8/16-bit outputs, none for
//! float outputs, which stay linear.
ToneOperator renderedFrameCurve(const std::string& out, const std::string& tonemap);

//! "X,Y" in pixels (finite numbers); nullopt when malformed.
std::optional<Point> parsePoint(const std::string& text);
//! "WIDTHxHEIGHT" (two integers); nullopt when malformed.
std::optional<std::pair<int, int>> parseSize(const std::string& text);

//! A float image read for a subcommand: decoded as readImage does, noise filtered, NaN/Inf
//! replaced with a warning, and (the same in every subcommand) more than 4 channels refused:
//! flarekit writes RGBA, so the others would be lost from the output.
//! `job` is the subcommand's memory per input pixel, checked against the budget from the header.
Result<LoadedImage> readInputImage(const std::string& path, const JobMemory& job);

//! An EXR input's extras (other channels, attributes, windows) for writing `out`: all of it to
//! an EXR; to another format a warning that its channels past RGBA are not written there.
std::shared_ptr<const ExrExtras> keptExtras(const LoadedImage& loaded, const std::string& in,
                                            const std::string& out);

//! The tail of every image-writing subcommand: `out` checked before any work (a bad path costs
//! nothing), the work, one atomic write, the result as an exit code (errors as one line).
struct ImageOutput {
    Image image;
    WriteOptions options;
};
int runImageJob(const std::string& out, const std::function<Result<ImageOutput>()>& work);
int runImage8Job(const std::string& out, const std::function<Result<Image8>()>& work);

#if FLAREKIT_HAS_GL
//! The headless GL context with Mesa's loader warnings held back: on failure its one line says
//! what was tried and what failed (with Mesa's first warning), instead of four lines.
Result<std::unique_ptr<gl::HeadlessGl>> createHeadlessGl();
//! A frame of width x height rendered with `msaa` samples per pixel in the current context:
//! refused when a side is over the context's limits (GL_MAX_TEXTURE_SIZE, renderbuffer,
//! viewport, framebuffer), naming `field` ("scene.json: image" gives "scene.json:
//! image.width: ..."), or when its render targets and copies are over the memory budget.
Status checkGlFrame(int width, int height, int msaa, const std::string& field);
#endif

//! The one-line error of an OpenGL feature in a build without OpenGL (FLAREKIT_GL=OFF).
Error builtWithoutGl(const std::string& what);

//! Writes a text file atomically (temporary file, then rename).
Status writeText(const std::string& path, const std::string& text);

//! Each subcommand adds itself to the app; its callback stores the exit code.
void addBlendCommand(CLI::App& app, int& exitCode);
void addApplyCommand(CLI::App& app, int& exitCode);
void addElementsCommand(CLI::App& app, int& exitCode);
void addPresetsCommand(CLI::App& app, int& exitCode);
void addVisibilityCommand(CLI::App& app, int& exitCode);
void addRenderCommand(CLI::App& app, int& exitCode);
void addLightsCommand(CLI::App& app, int& exitCode);
void addDemoCommand(CLI::App& app, int& exitCode);
void addPspCommand(CLI::App& app, int& exitCode);
void addPostFxCommand(CLI::App& app, int& exitCode);
void addLensCommand(CLI::App& app, int& exitCode);

}  // namespace flarekit::cli

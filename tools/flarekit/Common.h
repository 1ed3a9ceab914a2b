// SPDX-License-Identifier: Apache-2.0
// What every subcommand shares: turning library errors into one stderr line and an exit code
// (0 success, 2 bad input, 1 internal failure), warnings, and small argument parsers.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdio>
#include <functional>
#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/FirstLine.h"  // cappedLine, printable: every printed line
#include "core/LibraryNoise.h"
#include "core/SafeWrite.h"  // makeOutputDirectory, shared by every subcommand
#include "flarekit/Flare.h"
#include "flarekit/ImageIO.h"
#include "flarekit/PostFxParams.h"
#include "flarekit/Result.h"
#include "flarekit/job/ApplyJob.h"
#include "flarekit/job/Job.h"
#include "flarekit/job/PostFxJob.h"
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
//! The first line of `text`, cut to `max` characters.
std::string excerptLine(const std::string& text, std::size_t max);
void warn(const std::string& message);

//! readImage8 with library noise filtered.
inline Result<Image8> readImage8Quietly(const std::string& path) {
    LibraryNoiseFilter filter;
    return readImage8(path);
}

//! The --tonemap choices: `extra` (a command's own words, such as "auto" or "preset") and then the
//! curves' names as kToneOperatorNames types them, so a curve's name is written once.
std::vector<std::string> toneChoices(std::initializer_list<const char*> extra);
//! A library's list of choice names as CLI11 takes them (CLI::IsMember).
std::vector<std::string> choiceNames(std::span<const std::string_view> names);
//! The index of `text` in `names` (the enum's value), or -1.
int choiceIndex(std::span<const std::string_view> names, std::string_view text);

//! A rendered frame's curve (render, lights): `--tonemap NAME` for 8/16-bit outputs, none for
//! float outputs, which stay linear.
ToneOperator renderedFrameCurve(const std::string& out, const std::string& tonemap);

//! "X,Y" in pixels (finite numbers); nullopt when malformed.
std::optional<Point> parsePoint(const std::string& text);
//! "WIDTHxHEIGHT" (two integers); nullopt when malformed.
std::optional<std::pair<int, int>> parseSize(const std::string& text);

//! The tail of every image-writing subcommand: `out` checked before any work (a bad path costs
//! nothing), the work, one atomic write, the result as an exit code (errors as one line).
//! The compression the global options (--png-compression, --exr-compression, --exr-zip-level)
//! chose, set once while parsing; every file the CLI writes carries it in its WriteOptions.
EncodeSettings& encodeSettings();
int runImageJob(const std::string& out, const std::function<Result<ImageOutput>()>& work);
int runImage8Job(const std::string& out, const std::function<Result<Image8>()>& work);

//! The one-line error of an OpenGL feature in a build without OpenGL (FLAREKIT_GL=OFF).
Error builtWithoutGl(const std::string& what);

//! Each subcommand adds itself to the app; its callback stores the exit code.
void addBlendCommand(CLI::App& app, int& exitCode);
void addApplyCommand(CLI::App& app, int& exitCode);
void addElementsCommand(CLI::App& app, int& exitCode);
void addPresetsCommand(CLI::App& app, int& exitCode);
void addConvertCommand(CLI::App& app, int& exitCode);
void addVisibilityCommand(CLI::App& app, int& exitCode);
void addRenderCommand(CLI::App& app, int& exitCode);
void addLightsCommand(CLI::App& app, int& exitCode);
void addDemoCommand(CLI::App& app, int& exitCode);
void addPspCommand(CLI::App& app, int& exitCode);
void addPostFxCommand(CLI::App& app, int& exitCode);
void addLensCommand(CLI::App& app, int& exitCode);
void addSynthCommand(CLI::App& app, int& exitCode);
void addStudioCommand(CLI::App& app);
//! `flarekit studio ...`: runs flarekit-studio with the rest of the command line; the exit code
//! when it cannot.
int runStudioCommand(int argc, char** argv);
//! `lens render`, under the `lens` command.
void addLensRenderCommand(CLI::App* lens, int& exitCode);

}  // namespace flarekit::cli

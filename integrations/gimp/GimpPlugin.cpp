// SPDX-License-Identifier: Apache-2.0
// flarekit-gimp: the GIMP 2.10 plug-in behind Filters > Light and Shadow > flarekit Lens
// Flare... and the procedure plug-in-flarekit-lens-flare (Script-Fu, Python-Fu, batch mode).
// A plug-in runs as its own process: nothing thrown reaches GIMP, and every failure returns
// GIMP's execution error with the one-line message (shown as a GIMP message interactively).
#include <gegl.h>
#include <libgimp/gimp.h>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "DrawableFlare.h"
#include "GimpDialog.h"
#include "GimpSettings.h"
#include "core/InstallPaths.h"

// Where an installed plug-in finds the shipped presets and lenses, relative to its own folder
// (PREFIX/lib/gimp/2.0/plug-ins): CMake computes it from the install layout.
#ifndef FLAREKIT_PLUGIN_TO_PRESETS
#define FLAREKIT_PLUGIN_TO_PRESETS "../../../../share/flarekit/presets"
#endif
#ifndef FLAREKIT_PLUGIN_TO_MODULES
#define FLAREKIT_PLUGIN_TO_MODULES "../../../flarekit"
#endif

namespace {

using namespace flarekit;
using namespace flarekit::gimp;

constexpr int kFixedArgs = 3;  // run-mode, image, drawable

void query() {
    static std::vector<GimpParamDef> args;
    static std::vector<std::string> names, helps;
    args = {
        {GIMP_PDB_INT32, const_cast<gchar*>("run-mode"),
         const_cast<gchar*>("The run mode { RUN-INTERACTIVE (0), RUN-NONINTERACTIVE (1) }")},
        {GIMP_PDB_IMAGE, const_cast<gchar*>("image"), const_cast<gchar*>("Input image")},
        {GIMP_PDB_DRAWABLE, const_cast<gchar*>("drawable"), const_cast<gchar*>("Input drawable")}};
    for (const ProcedureArg& a : kProcedureArgs) {
        names.emplace_back(a.name);
        helps.emplace_back(a.help);
    }
    for (std::size_t i = 0; i < names.size(); ++i) {
        const GimpPDBArgType type =
            kProcedureArgs[i].type == ProcedureArg::Type::String ? GIMP_PDB_STRING
            : kProcedureArgs[i].type == ProcedureArg::Type::Int  ? GIMP_PDB_INT32
                                                                 : GIMP_PDB_FLOAT;
        args.push_back({type, names[i].data(), helps[i].data()});
    }
    gimp_install_procedure(
        kProcedure, "Lens flares in linear light from flarekit",
        "A sprite preset, the post-process chain or a lens prescription's traced ghosts on the "
        "light found in the image or placed by hand, computed in linear light at the image's "
        "precision (8-bit, 16-bit or 32-bit float), onto the layer or as a new layer in Addition "
        "mode. The same flare as the flarekit CLI on the same pixels.",
        "flarekit contributors", "flarekit contributors (Apache-2.0)", "2026",
        "flarekit _Lens Flare...", "RGB*, GRAY*", GIMP_PLUGIN, gint(args.size()), 0, args.data(),
        nullptr);
    gimp_plugin_menu_register(kProcedure, "<Image>/Filters/Light and Shadow");
}

//! The procedure's values into settings; an error names the argument.
Status settingsFrom(const GimpParam* param, int nparams, Settings& s) {
    if (nparams != kFixedArgs + kProcedureArgCount)
        return invalidInput(std::string(kProcedure) + ": expected " +
                            std::to_string(kFixedArgs + kProcedureArgCount) + " arguments, got " +
                            std::to_string(nparams));
    const GimpParam* p = param + kFixedArgs;
    const std::string mode = p[0].data.d_string ? p[0].data.d_string : "";
    s.mode = -1;
    for (std::size_t i = 0; i < std::size(host::kFlareModeNames); ++i)
        if (host::kFlareModeNames[i] == mode) s.mode = int(i);
    if (s.mode < 0)
        return invalidInput("mode: expected sprite, postfx or lens, got '" + mode + "'");
    s.setPreset(p[1].data.d_string ? p[1].data.d_string : "");
    s.findLight = p[2].data.d_int32 != 0;
    s.x = p[3].data.d_float, s.y = p[4].data.d_float;
    s.intensity = p[5].data.d_float, s.threshold = p[6].data.d_float;
    s.newLayer = p[7].data.d_int32 != 0;
    return checkSettings(s);
}

void run(const gchar*, gint nparams, const GimpParam* param, gint* nreturn, GimpParam** returned) {
    static GimpParam values[2];
    static std::string message;
    *nreturn = 1;
    *returned = values;
    values[0].type = GIMP_PDB_STATUS;
    values[0].data.d_status = GIMP_PDB_SUCCESS;
    auto fail = [&](GimpPDBStatusType status, const std::string& why) {
        message = why;
        values[0].data.d_status = status;
        values[1].type = GIMP_PDB_STRING;
        values[1].data.d_string = message.data();
        *nreturn = 2;
    };
    if (nparams < kFixedArgs)
        return fail(GIMP_PDB_CALLING_ERROR, "missing run-mode, image or drawable");
    const auto runMode = GimpRunMode(param[0].data.d_int32);
    const gint32 image = param[1].data.d_image;
    const gint32 drawable = param[2].data.d_drawable;
    try {
        // GIMP starts the installed file (a link to it in a user's plug-in folder is resolved
        // by /proc/self/exe): the presets are found from its folder.
        std::error_code ec;
        const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
        if (!ec)
            addShippedRoots(exe.parent_path() / FLAREKIT_PLUGIN_TO_PRESETS,
                            exe.parent_path() / FLAREKIT_PLUGIN_TO_MODULES);
        gegl_init(nullptr, nullptr);
        Settings settings;
        switch (runMode) {
            case GIMP_RUN_INTERACTIVE:
                gimp_get_data(kProcedure, &settings);
                if (!checkSettings(settings)) settings = Settings{};
                if (!runDialog(image, drawable, settings)) {
                    values[0].data.d_status = GIMP_PDB_CANCEL;
                    return;
                }
                break;
            case GIMP_RUN_NONINTERACTIVE:
                if (Status s = settingsFrom(param, nparams, settings); !s)
                    return fail(GIMP_PDB_CALLING_ERROR, s.error().message);
                break;
            case GIMP_RUN_WITH_LAST_VALS:
                gimp_get_data(kProcedure, &settings);
                if (!checkSettings(settings)) settings = Settings{};
                break;
        }
        gimp_progress_init("flarekit lens flare");
        Status done = flareDrawable(image, drawable, settings);
        if (!done) {
            if (runMode == GIMP_RUN_INTERACTIVE) gimp_message(done.error().message.c_str());
            return fail(GIMP_PDB_EXECUTION_ERROR, done.error().message);
        }
        gimp_progress_update(1.0);
        if (runMode != GIMP_RUN_NONINTERACTIVE) gimp_displays_flush();
        if (runMode == GIMP_RUN_INTERACTIVE) gimp_set_data(kProcedure, &settings, sizeof settings);
    } catch (const std::exception& e) {
        fail(GIMP_PDB_EXECUTION_ERROR, std::string("flarekit: internal error: ") + e.what());
    } catch (...) {
        fail(GIMP_PDB_EXECUTION_ERROR, "flarekit: internal error");
    }
}

const GimpPlugInInfo kPlugIn = {nullptr, nullptr, query, run};

}  // namespace

// libgimp's MAIN(): the entry point GIMP starts the plug-in through.
int main(int argc, char* argv[]) {
    // Run by hand (GIMP starts it with -gimp and its pipes): the procedure's arguments.
    if (argc == 2 && std::string(argv[1]) == "--markdown") {
        std::fputs(markdownTable().c_str(), stdout);
        return std::fflush(stdout) == 0 ? 0 : 1;
    }
    return gimp_main(&kPlugIn, argc, argv);
}

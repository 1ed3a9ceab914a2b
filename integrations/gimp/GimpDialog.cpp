// SPDX-License-Identifier: Apache-2.0
#include "GimpDialog.h"

#include <libgimp/gimpui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "DrawableFlare.h"
#include "flarekit/Color.h"

namespace flarekit::gimp {

namespace {

//! The preview's longest side: large enough to place a light to a few pixels of a photograph,
//! small enough that a sprite flare redraws while the user drags a slider.
constexpr int kPreviewSize = 480;

struct Dialog {
    gint32 image = 0, drawable = 0;
    Settings* settings = nullptr;
    double scale = 1;
    std::optional<PixelInput> plate;  //!< the drawable at the preview's size, read once
    GtkWidget *preview = nullptr, *status = nullptr, *presetCombo = nullptr;
    GtkWidget *findLight = nullptr, *xSpin = nullptr, *ySpin = nullptr;
    guint idle = 0;
    bool filling = false;  //!< the preset list is being refilled: not an edit
};

//! linear RGBA floats to the preview's 8-bit sRGB, a cross on a placed light.
GdkPixbuf* toPixbuf(const Image& image, std::optional<Point> light) {
    const int w = image.width(), h = image.height();
    GdkPixbuf* pixbuf = gdk_pixbuf_new(GDK_COLORSPACE_RGB, FALSE, 8, w, h);
    guchar* pixels = gdk_pixbuf_get_pixels(pixbuf);
    const int stride = gdk_pixbuf_get_rowstride(pixbuf);
    for (int y = 0; y < h; ++y)
        encodeSrgb8(image.row(y), std::size_t(w), 3, pixels + std::size_t(y) * std::size_t(stride));
    if (light) {
        const int cx = int(std::floor(light->x)), cy = int(std::floor(light->y));
        for (int d = -6; d <= 6; ++d) {
            for (auto [x, y] : {std::pair{cx + d, cy}, std::pair{cx, cy + d}}) {
                if (x < 0 || y < 0 || x >= w || y >= h) continue;
                guchar* p = pixels + std::size_t(y) * std::size_t(stride) + std::size_t(x) * 3;
                p[0] = 0, p[1] = 255, p[2] = 255;
            }
        }
    }
    return pixbuf;
}

void render(Dialog& d) {
    if (!d.plate) {
        auto read = readDrawable(d.image, d.drawable, d.scale);
        if (!read) {
            gtk_label_set_text(GTK_LABEL(d.status), read.error().message.c_str());
            return;
        }
        d.plate = std::move(*read);
    }
    const Settings& s = *d.settings;
    std::string line = "flare drawn";
    if (s.findLight && s.flareMode() == host::FlareMode::Sprite) {
        // Where the finder puts the light (or why it finds none), in image pixels.
        const LightSearch found =
            findLights(d.plate->image, host::searchOptions(flareRequest(s, d.drawable, d.scale)));
        gint ox = 0, oy = 0;
        gimp_drawable_offsets(d.drawable, &ox, &oy);
        char text[96];
        if (found.lights.empty())
            line = "no light found: " + found.whyNone + " (click the preview to place one)";
        else if (std::snprintf(text, sizeof text, "light found at %.0f, %.0f",
                               found.lights[0].position.x / d.scale + ox,
                               found.lights[0].position.y / d.scale + oy) > 0)
            line = text;
    }
    Image shown = d.plate->image;
    if (Status ok = checkSettings(s); !ok) {
        line = ok.error().message;
    } else if (auto look = host::Look::load(s.flareMode(), s.presetName()); !look) {
        line = look.error().message;
    } else {
        auto flared = host::drawFlare(*look, flareRequest(s, d.drawable, d.scale), *d.plate);
        if (flared)
            shown = std::move(*flared);
        else
            line = flared.error().message;
    }
    const host::FlareRequest placed = flareRequest(s, d.drawable, d.scale);
    GdkPixbuf* pixbuf = toPixbuf(shown, placed.light);
    gtk_image_set_from_pixbuf(GTK_IMAGE(d.preview), pixbuf);
    g_object_unref(pixbuf);
    gtk_label_set_text(GTK_LABEL(d.status), line.c_str());
}

gboolean renderWhenIdle(gpointer data) {
    auto& d = *static_cast<Dialog*>(data);
    d.idle = 0;
    render(d);
    return G_SOURCE_REMOVE;
}

void changed(Dialog& d) {
    if (!d.idle) d.idle = g_idle_add(renderWhenIdle, &d);
}

void fillPresets(Dialog& d) {
    d.filling = true;
    GtkComboBoxText* combo = GTK_COMBO_BOX_TEXT(d.presetCombo);
    gtk_list_store_clear(GTK_LIST_STORE(gtk_combo_box_get_model(GTK_COMBO_BOX(combo))));
    const std::string current = host::lookName(d.settings->flareMode(), d.settings->presetName());
    int active = -1, index = 0;
    for (const std::string& name : host::lookNames(d.settings->flareMode())) {
        gtk_combo_box_text_append_text(combo, name.c_str());
        if (name == current) active = index;
        ++index;
    }
    if (active >= 0)
        gtk_combo_box_set_active(GTK_COMBO_BOX(combo), active);
    else
        gtk_entry_set_text(GTK_ENTRY(gtk_bin_get_child(GTK_BIN(combo))), current.c_str());
    d.filling = false;
}

void onMode(GtkComboBox* combo, Dialog* d) {
    d->settings->mode = std::max(0, gtk_combo_box_get_active(combo));
    d->settings->setPreset("");
    fillPresets(*d);
    changed(*d);
}
void onPreset(GtkComboBox* combo, Dialog* d) {
    if (d->filling) return;
    gchar* text = gtk_combo_box_text_get_active_text(GTK_COMBO_BOX_TEXT(combo));
    d->settings->setPreset(text ? text : "");
    g_free(text);
    changed(*d);
}
void onToggle(GtkToggleButton* button, int* value) {
    *value = gtk_toggle_button_get_active(button) ? 1 : 0;
}
void onNumber(GtkSpinButton* spin, double* value) {
    *value = gtk_spin_button_get_value(spin);
}
gboolean onClick(GtkWidget* box, GdkEventButton* event, Dialog* d) {
    // The image is centred in its box: the click's offset from the image's corner, scaled up.
    GtkAllocation area;
    gtk_widget_get_allocation(box, &area);
    const int w = d->plate ? d->plate->image.width() : 0;
    const int h = d->plate ? d->plate->image.height() : 0;
    const double left = (area.width - w) / 2.0, top = (area.height - h) / 2.0;
    gint ox = 0, oy = 0;
    gimp_drawable_offsets(d->drawable, &ox, &oy);
    gtk_spin_button_set_value(GTK_SPIN_BUTTON(d->xSpin), (event->x - left) / d->scale + ox);
    gtk_spin_button_set_value(GTK_SPIN_BUTTON(d->ySpin), (event->y - top) / d->scale + oy);
    gtk_toggle_button_set_active(GTK_TOGGLE_BUTTON(d->findLight), FALSE);
    return TRUE;
}

GtkWidget* spin(Dialog& d, double* value, double lo, double hi, double step, int digits) {
    GtkWidget* s = gtk_spin_button_new_with_range(lo, hi, step);
    gtk_spin_button_set_digits(GTK_SPIN_BUTTON(s), guint(digits));
    gtk_spin_button_set_value(GTK_SPIN_BUTTON(s), *value);
    g_signal_connect(s, "value-changed", G_CALLBACK(onNumber), value);
    g_signal_connect_swapped(s, "value-changed", G_CALLBACK(+[](Dialog* dd) { changed(*dd); }), &d);
    return s;
}

GtkWidget* check(Dialog& d, const char* label, int* value) {
    GtkWidget* c = gtk_check_button_new_with_mnemonic(label);
    gtk_toggle_button_set_active(GTK_TOGGLE_BUTTON(c), *value != 0);
    g_signal_connect(c, "toggled", G_CALLBACK(onToggle), value);
    g_signal_connect_swapped(c, "toggled", G_CALLBACK(+[](Dialog* dd) { changed(*dd); }), &d);
    return c;
}

void attach(GtkWidget* table, int row, const char* label, GtkWidget* widget) {
    GtkWidget* l = gtk_label_new_with_mnemonic(label);
    gtk_misc_set_alignment(GTK_MISC(l), 0.0, 0.5);
    gtk_table_attach(GTK_TABLE(table), l, 0, 1, guint(row), guint(row + 1), GTK_FILL, GTK_FILL, 0,
                     0);
    gtk_table_attach(GTK_TABLE(table), widget, 1, 2, guint(row), guint(row + 1),
                     GtkAttachOptions(GTK_EXPAND | GTK_FILL), GTK_FILL, 0, 0);
}

}  // namespace

bool runDialog(gint32 image, gint32 drawable, Settings& settings) {
    gimp_ui_init(kBinary, FALSE);
    Dialog d;
    d.image = image, d.drawable = drawable, d.settings = &settings;
    const int width = gimp_drawable_width(drawable), height = gimp_drawable_height(drawable);
    d.scale = std::min(1.0, double(kPreviewSize) / double(std::max(width, height)));

    GtkWidget* dialog = gimp_dialog_new("flarekit Lens Flare", kBinary, nullptr, GtkDialogFlags(0),
                                        gimp_standard_help_func, kProcedure, "_Cancel",
                                        GTK_RESPONSE_CANCEL, "_OK", GTK_RESPONSE_OK, nullptr);
    GtkWidget* box = gtk_vbox_new(FALSE, 8);
    gtk_container_set_border_width(GTK_CONTAINER(box), 12);
    gtk_box_pack_start(GTK_BOX(gtk_dialog_get_content_area(GTK_DIALOG(dialog))), box, TRUE, TRUE,
                       0);

    GtkWidget* events = gtk_event_box_new();
    d.preview = gtk_image_new();
    gtk_container_add(GTK_CONTAINER(events), d.preview);
    g_signal_connect(events, "button-press-event", G_CALLBACK(onClick), &d);
    gtk_box_pack_start(GTK_BOX(box), events, TRUE, TRUE, 0);
    d.status = gtk_label_new("");
    gtk_misc_set_alignment(GTK_MISC(d.status), 0.0, 0.5);
    gtk_box_pack_start(GTK_BOX(box), d.status, FALSE, FALSE, 0);

    GtkWidget* table = gtk_table_new(7, 2, FALSE);
    gtk_table_set_col_spacings(GTK_TABLE(table), 8);
    gtk_table_set_row_spacings(GTK_TABLE(table), 4);
    gtk_box_pack_start(GTK_BOX(box), table, FALSE, FALSE, 0);

    GtkWidget* mode = gtk_combo_box_text_new();
    for (std::string_view m : host::kFlareModeNames)
        gtk_combo_box_text_append_text(GTK_COMBO_BOX_TEXT(mode), std::string(m).c_str());
    gtk_combo_box_set_active(GTK_COMBO_BOX(mode), settings.mode);
    attach(table, 0, "_Mode:", mode);
    d.presetCombo = gtk_combo_box_text_new_with_entry();
    attach(table, 1, "_Preset or lens:", d.presetCombo);
    fillPresets(d);
    g_signal_connect(mode, "changed", G_CALLBACK(onMode), &d);
    g_signal_connect(d.presetCombo, "changed", G_CALLBACK(onPreset), &d);

    d.findLight = check(d, "_Find the light (or click the preview)", &settings.findLight);
    gtk_table_attach(GTK_TABLE(table), d.findLight, 0, 2, 2, 3, GTK_FILL, GTK_FILL, 0, 0);
    // Off-canvas lights: a frame's width beyond each side still throws ghosts across it.
    d.xSpin = spin(d, &settings.x, -double(width), 2.0 * width, 1, 1);
    d.ySpin = spin(d, &settings.y, -double(height), 2.0 * height, 1, 1);
    attach(table, 3, "Light _x:", d.xSpin);
    attach(table, 4, "Light _y:", d.ySpin);
    attach(table, 5,
           "_Intensity:", spin(d, &settings.intensity, kIntensityMin, kIntensityMax, 0.05, 2));
    attach(table, 6,
           "_Threshold (0: preset's):", spin(d, &settings.threshold, 0, kThresholdMax, 0.05, 2));
    GtkWidget* layer = check(d, "As a new _layer (Addition)", &settings.newLayer);
    gtk_box_pack_start(GTK_BOX(box), layer, FALSE, FALSE, 0);

    gtk_widget_show_all(dialog);
    render(d);
    const bool ok = gimp_dialog_run(GIMP_DIALOG(dialog)) == GTK_RESPONSE_OK;
    if (d.idle) g_source_remove(d.idle);
    gtk_widget_destroy(dialog);
    return ok;
}

}  // namespace flarekit::gimp

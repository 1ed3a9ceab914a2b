// SPDX-License-Identifier: Apache-2.0
// The contact sheet of `flarekit elements`: every element of a preset in its own cell, with a
// label drawn by OpenImageIO's text renderer (through its module, core/codecs/OiioModule.h).

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/codecs/OiioModule.h"
#include "flarekit/Flare.h"
#include "flarekit/Limits.h"

namespace flarekit {

namespace {
//! Share of a cell's half-size the element's radius takes, leaving room for the label.
constexpr float kCellFill = 0.8f;
constexpr int kMaxColumns = 4;

std::string label(std::size_t index, const ElementParams& e) {
    std::ostringstream os;
    os << index << ": " << elementTypeName(e.type) << "  t=" << e.t << "  size=" << e.size;
    return os.str();
}
}  // namespace

Result<ContactSheet> renderContactSheet(const Preset& preset, int cellSize) {
    if (cellSize < 32 || cellSize > 4096) {
        return invalidInput("cell size: expected an integer in [32, 4096], got " +
                            std::to_string(cellSize));
    }
    const int n = int(preset.elements.size());
    const int columns = std::min(n, kMaxColumns), rows = (n + columns - 1) / columns;
    // The sheet's RGBA floats, the OIIO canvas's label rendering and the largest sprite (a
    // cell), then the encoded samples: ~24 bytes per sheet pixel.
    const double sheetPixels = double(columns) * rows * double(cellSize) * cellSize;
    if (Status s = checkMemory("elements: a sheet of " + std::to_string(n) + " cells of " +
                                   std::to_string(cellSize) + " px",
                               sheetPixels * 24.0 + 16.0 * cellSize * cellSize * 4.0);
        !s) {
        return s.error();
    }
    ContactSheet sheet;
    sheet.image = Image(columns * cellSize, rows * cellSize);
    sheet.image.fill({0.f, 0.f, 0.f, 1.f});

    const codec::OiioModule* text = codec::oiioModule();
    sheet.labelled = text != nullptr;
    const int fontSize = std::max(10, cellSize / 16);
    const float labelColour[] = {0.8f, 0.8f, 0.8f, 1.f};

    for (int i = 0; i < n; ++i) {
        ElementParams e = preset.elements[std::size_t(i)];
        e.intensity *= preset.intensity;
        const float radius = kCellFill * 0.5f * float(cellSize) / std::max(1.f, e.aspect);
        const Image sprite = renderElement(e, radius);
        // Sprite centred in its cell, clipped to the cell (a wide streak may overhang it).
        const int cellX = (i % columns) * cellSize, cellY = (i / columns) * cellSize;
        const int left = cellX + cellSize / 2 - sprite.width() / 2,
                  top = cellY + cellSize / 2 - sprite.height() / 2;
        const int x0 = std::max(left, cellX),
                  x1 = std::min(left + sprite.width(), cellX + cellSize);
        const int y0 = std::max(top, cellY), y1 = std::min(top + sprite.height(), cellY + cellSize);
        for (int y = y0; y < y1; ++y) {
            compositeSpan(BlendMode::Add, &sprite.at(x0 - left, y - top).r,
                          &sheet.image.at(x0, y).r, std::size_t(x1 - x0));
        }
        if (sheet.labelled) {
            sheet.labelled = text->renderText(
                sheet.image.data(), sheet.image.width(), sheet.image.height(), cellX + fontSize / 2,
                cellY + fontSize + fontSize / 2, label(std::size_t(i), e), fontSize,
                codec::kLabelFontFile, labelColour);
        }
    }
    return sheet;
}

}  // namespace flarekit

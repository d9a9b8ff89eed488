#pragma once

// How the pictures look, the same in every painter and writer: the themes and
// the color of each element. Colors from the Okabe-Ito palette where meanings
// must not be confused (DOP, vanishing lines, z-fighting), readable by
// colorblind people. No VTK, no Qt.

#include <array>

#include "viewpipe/evaluated_scene.hpp"

namespace viewpipe {

enum class Theme { Dark, Light };

struct Rgb {
    double r, g, b;
};

Rgb elementColor(Element element, Theme theme);
// Object faces: a light tint under their dark (or light) edges.
Rgb faceColor(Theme theme);
// An element's color: objects' surfaces take faceColor, everything else elementColor.
Rgb styledColor(Element element, bool surface, Theme theme);
Rgb backgroundColor(Theme theme, bool projectedView);
// 0 to 255 a channel, as image data stores colors.
std::array<unsigned char, 3> toBytes(const Rgb& color);

// The depth bands' ramp from near (yellow) to far (violet); no red or orange
// in it, which mark z-fighting.
extern const std::array<Rgb, 5> kBandRamp;
// The raster effect's pixels, one color per object.
extern const std::array<Rgb, 4> kRasterPalette;

} // namespace viewpipe

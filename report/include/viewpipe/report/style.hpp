#pragma once

// How the pictures look, the same in every painter and writer: the themes and
// the color of each element. Colors from the Okabe-Ito palette where meanings
// must not be confused (DOP, vanishing lines, z-fighting), readable by
// colorblind people. No VTK, no Qt.

#include <array>
#include <string>

#include "viewpipe/evaluated_scene.hpp"

namespace viewpipe::report {

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
// Behind each label and tick number, its box in the picture's background at
// this opacity: the lines it could not keep off run faintly under it, not
// through its letters (as a map sets names over roads).
constexpr double kLabelBackdropOpacity = 0.75;
// Text sizes in pixels. An exported picture sets its labels and captions at
// least 2.4 % of its width and everything else (tick numbers, the legend, the
// effects' note) at least 1.8 %: 8 pt and 6 pt when the picture is 12 cm
// wide, a column of lecture notes or a 16:9 Beamer slide. `textScale` enlarges
// both (1 is 100 %), as the app's Larger Text does. Labels are never under 10 px.
constexpr double kLabelWidthShare = 0.024, kSmallWidthShare = 0.018;
// `widthShare`: the labels' share of the width, another picture's than a single stage's (a storyboard's).
double exportLabelSize(int widthPixels, double textScale, double widthShare = kLabelWidthShare);
// Text scales in whole percent, 100 the default size: `export --text-scale`,
// `open --text-scale` and the app's Larger and Smaller Text share this range.
constexpr int kMinTextScale = 50, kMaxTextScale = 400;
// Throws InputError naming `field` unless kMinTextScale <= percent <= kMaxTextScale.
void checkTextScale(int percent, const std::string& field);
// The smaller text beside labels of `labelSize`: three quarters, at least 8 px.
double smallTextSize(double labelSize);

// 0 to 255 a channel, as image data stores colors.
std::array<unsigned char, 3> toBytes(const Rgb& color);

// The depth bands' ramp from near (yellow) to far (violet); no red or orange
// in it, which mark z-fighting.
extern const std::array<Rgb, 5> kBandRamp;
// Band k's color: alternating light and dark steps along the ramp, so that neighbouring bands always differ.
Rgb bandColor(const DepthBands& bands, int k);
// The band a level lies in, the first or last where it lies beyond them (as a lookup table over the bands maps it).
int bandOf(const DepthBands& bands, double level);
// Where the depth buffer stores nothing (the point lies outside the volume): grey, a quarter opaque.
constexpr Rgb kNoBandColor{0.5, 0.5, 0.5};
constexpr double kNoBandOpacity = 0.25;
// The raster effect's pixels, one color per object.
extern const std::array<Rgb, 4> kRasterPalette;

} // namespace viewpipe::report

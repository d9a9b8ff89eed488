#include "viewpipe/report/style.hpp"

#include "viewpipe/error.hpp"

#include <algorithm>
#include <cmath>

namespace viewpipe::report {

const std::array<Rgb, 5> kBandRamp = {
    {{0.99, 0.91, 0.15}, {0.37, 0.79, 0.38}, {0.13, 0.57, 0.55}, {0.23, 0.32, 0.55}, {0.27, 0.00, 0.33}}};

const std::array<Rgb, 4> kRasterPalette = {{{90 / 255.0, 140 / 255.0, 230 / 255.0},
                                            {230 / 255.0, 120 / 255.0, 60 / 255.0},
                                            {80 / 255.0, 190 / 255.0, 110 / 255.0},
                                            {200 / 255.0, 90 / 255.0, 200 / 255.0}}};

Rgb bandColor(const DepthBands& bands, int k)
{
    const double t = bands.count > 1 ? 4.0 * k / (bands.count - 1) : 0;
    const std::size_t i = std::size_t(std::min(int(t), 3));
    const double f = t - double(i), shade = k % 2 ? 0.72 : 1.0;
    const Rgb& a = kBandRamp[i];
    const Rgb& b = kBandRamp[i + 1];
    return {shade * (a.r + f * (b.r - a.r)), shade * (a.g + f * (b.g - a.g)), shade * (a.b + f * (b.b - a.b))};
}

int bandOf(const DepthBands& bands, double level)
{
    return std::clamp(int(std::floor((level - bands.first) / bands.levelsPerBand)), 0, bands.count - 1);
}

Rgb faceColor(Theme theme)
{
    return theme == Theme::Dark ? Rgb{0.45, 0.55, 0.80} : Rgb{0.62, 0.70, 0.90};
}

Rgb styledColor(Element element, bool surface, Theme theme)
{
    return element == Element::Objects && surface ? faceColor(theme) : elementColor(element, theme);
}

Rgb elementColor(Element element, Theme theme)
{
    const bool dark = theme == Theme::Dark;
    switch (element) {
    case Element::Objects: return dark ? Rgb{0.92, 0.92, 0.95} : Rgb{0.10, 0.10, 0.15};
    case Element::WorldAxes: return dark ? Rgb{0.75, 0.75, 0.75} : Rgb{0.35, 0.35, 0.35};
    case Element::ViewAxes: return dark ? Rgb{1.00, 0.65, 0.10} : Rgb{0.90, 0.55, 0.00}; // orange
    case Element::Prp: return dark ? Rgb{1.00, 0.85, 0.20} : Rgb{0.70, 0.50, 0.00};
    case Element::Window: return dark ? Rgb{0.30, 0.75, 1.00} : Rgb{0.00, 0.40, 0.80}; // sky blue
    case Element::Dop: return dark ? Rgb{0.90, 0.55, 0.80} : Rgb{0.70, 0.25, 0.55};    // reddish purple
    case Element::Volume: return dark ? Rgb{0.55, 0.65, 1.00} : Rgb{0.35, 0.45, 0.85};
    case Element::FrontPlane: return dark ? Rgb{0.35, 0.90, 0.45} : Rgb{0.10, 0.60, 0.20};
    case Element::BackPlane: return elementColor(Element::Volume, theme); // the volume's far face; purple is the DOP's
    case Element::Projectors: return dark ? Rgb{0.60, 0.60, 0.65} : Rgb{0.55, 0.55, 0.60};
    case Element::Canonical: return dark ? Rgb{1.00, 1.00, 1.00} : Rgb{0.00, 0.00, 0.00};
    case Element::Frame: return dark ? Rgb{0.38, 0.40, 0.45} : Rgb{0.72, 0.72, 0.76};
    case Element::Vanishing: return dark ? Rgb{0.00, 0.80, 0.60} : Rgb{0.00, 0.55, 0.40}; // bluish green
    // Vermillion: in neither the depth bands' ramp nor the other elements.
    case Element::ZFighting: return dark ? Rgb{1.00, 0.37, 0.05} : Rgb{0.84, 0.30, 0.00};
    case Element::Traced: return dark ? Rgb{1.00, 1.00, 1.00} : Rgb{0.00, 0.00, 0.00};
    }
    return {1, 1, 1};
}

std::array<unsigned char, 3> toBytes(const Rgb& color)
{
    auto byte = [](double channel) { return static_cast<unsigned char>(std::lround(255 * channel)); };
    return {byte(color.r), byte(color.g), byte(color.b)};
}

double exportLabelSize(int widthPixels, double textScale, double widthShare)
{
    return std::max(10.0, std::ceil(widthShare * widthPixels * textScale)); // readable however small the picture
}

void checkTextScale(int percent, const std::string& field)
{
    if (percent < kMinTextScale || percent > kMaxTextScale)
        throw InputError(field, "must be a whole percent from " + std::to_string(kMinTextScale) + " to " +
                                    std::to_string(kMaxTextScale) + " (got " + std::to_string(percent) + ")");
}

double smallTextSize(double labelSize)
{
    return std::max(8.0, std::ceil(kSmallWidthShare / kLabelWidthShare * labelSize));
}

Rgb backgroundColor(Theme theme, bool projectedView)
{
    const bool dark = theme == Theme::Dark;
    if (projectedView)
        return dark ? Rgb{0.07, 0.08, 0.10} : Rgb{0.96, 0.96, 0.97};
    return dark ? Rgb{0.11, 0.12, 0.14} : Rgb{1.0, 1.0, 1.0};
}

} // namespace viewpipe::report

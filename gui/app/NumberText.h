#pragma once

// Numbers as the app's fields show and read them: exact doubles in their
// shortest round-trip form, read in the C locale, never rounded.

#include <QString>

namespace viewpipe::gui {

// The shortest text that reads back as `value` ("infinity" for +inf).
QString numberText(double value);
// Reads a number in the C locale (a '.' decimal point, an optional exponent),
// correctly rounded; returns why the text is not one, or nothing.
QString readNumber(const QString& text, bool infinityAllowed, double& value);
// The same double, bit for bit (0 and -0 differ).
bool sameBits(double a, double b);

} // namespace viewpipe::gui

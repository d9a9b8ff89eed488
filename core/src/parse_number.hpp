#pragma once

// Numbers read from text whatever the locale (mesh files, typed answers).

#include <optional>
#include <string_view>

namespace viewpipe {

// A decimal number, as C++ writes one; nothing when the text is not one. An
// overflow gives an infinity (refused later as not finite), an underflow zero.
std::optional<double> parseDouble(std::string_view token);

} // namespace viewpipe

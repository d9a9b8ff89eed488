#pragma once

#include <stdexcept>
#include <string>

namespace viewpipe {

// The one error type for bad input: names the offending field (a path such as
// "view.vup" or "objects[2].min") and the reason. Caught at the CLI boundary
// (exit 2) and at the GUI slot boundary (shown inline, last valid state kept).
class InputError : public std::runtime_error {
public:
    InputError(std::string field, std::string reason)
        : std::runtime_error(field + ": " + reason), field_(std::move(field)), reason_(std::move(reason)) {}

    const std::string& field() const noexcept { return field_; }
    const std::string& reason() const noexcept { return reason_; }

private:
    std::string field_;
    std::string reason_;
};

} // namespace viewpipe

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

    // A syntax error at a place in a text file rather than in a field: field()
    // reads "LINE:COLUMN" (1-based).
    static InputError at(std::size_t line, std::size_t column, std::string reason)
    {
        InputError error(std::to_string(line) + ":" + std::to_string(column), std::move(reason));
        error.position_ = true;
        return error;
    }

    const std::string& field() const noexcept { return field_; }
    const std::string& reason() const noexcept { return reason_; }
    bool isPosition() const noexcept { return position_; }

    // The CLI's one line about `file`: "FILE: field.path: reason", or for a
    // position "FILE:LINE:COLUMN: reason", the form editors jump to.
    std::string describe(const std::string& file) const { return file + (position_ ? ":" : ": ") + what(); }

private:
    std::string field_;
    std::string reason_;
    bool position_ = false;
};

} // namespace viewpipe

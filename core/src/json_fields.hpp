#pragma once

// Reading JSON with the path of each field in every refusal ("view.vup[2]",
// "steps[3].question.answer"; "$" is the root): the scene and lesson readers'.

#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "viewpipe/error.hpp"
#include "viewpipe/linalg.hpp"

namespace viewpipe::fields {

using Json = nlohmann::json;

// What a value is, for "(got ...)": a text quoted (shortened), a number as written, else its kind.
std::string found(const Json& j);
std::string child(const std::string& parent, const std::string& key);
std::string element(const std::string& parent, std::size_t index);
// An object with only `allowed` keys and every `required` one.
void requireObject(const Json& j, const std::string& path, const std::set<std::string>& allowed,
                   const std::set<std::string>& required);
// A finite number; while a TypedExpressions scope is open, also an exact
// expression as a string ("20*sqrt(2)"), read as its nearest double and kept
// as typed in the scope's map by field path.
double readNumber(const Json& j, const std::string& path);
// An exact expression as typed (parseExact), as its nearest double; InputError(path, the parser's reason)
// where it is none, or too large for a double.
double readExpression(const std::string& text, const std::string& path);
class TypedExpressions {
public:
    explicit TypedExpressions(std::map<std::string, std::string>& into);
    ~TypedExpressions();
    TypedExpressions(const TypedExpressions&) = delete;
    TypedExpressions& operator=(const TypedExpressions&) = delete;

private:
    std::map<std::string, std::string>* previous_;
};
std::vector<double> readNumbers(const Json& j, const std::string& path, std::size_t count);
Vec3<double> readVec3(const Json& j, const std::string& path);
std::string readString(const Json& j, const std::string& path);
// A whole file; InputError("$", "cannot read the WHAT file: reason") when it cannot be read.
std::string readInputFile(const std::filesystem::path& file, const std::string& what);
// Syntax errors at LINE:COLUMN; a number too large for a double refused with its field path.
Json parseJson(const std::string& text);

} // namespace viewpipe::fields

#pragma once

// The page's data as JSON, shared by the web export (web_page.cpp) and the
// core compiled for the page (web/module.cpp), which makes it anew on every edit.

#include <nlohmann/json.hpp>

#include <string>

#include "viewpipe/report/web_page.hpp"

namespace viewpipe::report {

std::string base64(const void* data, std::size_t size);
// A scene as the page draws it: its primitives, labels and markers, each
// stage's views and matrices, the projected view; not the scene's source.
nlohmann::json sceneData(const EvaluatedScene& scene, const WebPageViews& views);
// A lesson's question as the page asks it.
nlohmann::json questionData(const Question& question);
// JSON to go inside <script>: no text in it can end the element.
std::string scriptJson(const nlohmann::json& data);

} // namespace viewpipe::report

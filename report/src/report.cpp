#include "viewpipe/report/report.hpp"

#include <algorithm>
#include <iomanip>
#include <limits>
#include <sstream>
#include <map>
#include <set>
#include <type_traits>

#ifdef VIEWPIPE_WIDE_SCALARS
#include "viewpipe/accuracy.hpp" // setReferenceBits
#endif
#include "viewpipe/api.hpp"
#include "viewpipe/classical.hpp"
#include "viewpipe/format.hpp"

namespace viewpipe::report {
namespace {

using Json = nlohmann::json;

// Values wider than double go out as strings with all their digits.
template <class T> Json number(const T& x)
{
    if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double> || isExactScalar<T>) {
        return static_cast<double>(x);
    } else if constexpr (std::is_same_v<T, long double>) {
        std::ostringstream out;
        out << std::setprecision(std::numeric_limits<long double>::max_digits10) << x;
        return out.str();
    } else {
        return x.str(0, std::ios_base::scientific); // every digit the value has
    }
}

template <class T> Json matrixJson(const Mat4<T>& m)
{
    Json rows = Json::array();
    for (int r = 0; r < 4; ++r)
        rows.push_back({number(m(r, 0)), number(m(r, 1)), number(m(r, 2)), number(m(r, 3))});
    return rows;
}

template <class T, int N> Json vectorJson(const Eigen::Matrix<T, N, 1>& v)
{
    Json out = Json::array();
    for (int i = 0; i < N; ++i)
        out.push_back(number(v[i]));
    return out;
}

// Six significant digits, in every precision; exact values as they are, the
// others of the exact precision marked ~.
template <class T> std::string shortNumber(const T& x)
{
    if constexpr (isExactScalar<T>)
        return x.isExact() ? x.text() : "~" + formatSignificant(static_cast<double>(x), 6);
    else
        return formatSignificant(static_cast<double>(x), 6);
}

template <class T, int N> Json exactJson(const Eigen::Matrix<T, N, 1>& v)
{
    Json out = Json::array();
    for (int i = 0; i < N; ++i)
        out.push_back(v[i].text());
    return out;
}

// Rows of exact entries; an inexact one is listed in `inexact` under `path`.
Json exactJson(const Mat4<Exact>& m, const std::string& path, Json& inexact)
{
    Json rows = Json::array();
    for (int r = 0; r < 4; ++r) {
        Json row = Json::array();
        for (int c = 0; c < 4; ++c) {
            row.push_back(m(r, c).text());
            if (!m(r, c).isExact())
                inexact.push_back({{"path", path + "[" + std::to_string(r) + "][" + std::to_string(c) + "]"},
                                   {"reason", m(r, c).inexactReason()}});
        }
        rows.push_back(row);
    }
    return rows;
}

// The typed point in a precision: a float type rounds it once, a wider one takes its digits.
template <class T> T scalarOf(const Exact& x)
{
    if constexpr (isExactScalar<T>)
        return x;
    else if constexpr (std::is_floating_point_v<T>)
        return static_cast<T>(x);
    else
        return T(x.approximation().str(60));
}

template <class T> std::vector<std::string> matrixLines(const Mat4<T>& m)
{
    std::size_t width = 0;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            width = std::max(width, shortNumber(m(r, c)).size());
    std::vector<std::string> lines;
    for (int r = 0; r < 4; ++r) {
        std::ostringstream line;
        line << "[";
        for (int c = 0; c < 4; ++c)
            line << " " << std::setw(int(width)) << shortNumber(m(r, c));
        line << " ]";
        lines.push_back(line.str());
    }
    return lines;
}

void printSideBySide(std::ostream& out, const std::vector<std::string>& left, const std::vector<std::string>& right,
                     const std::string& leftTitle, const std::string& rightTitle)
{
    std::size_t width = leftTitle.size();
    for (const std::string& line : left)
        width = std::max(width, line.size());
    out << "    " << std::left << std::setw(int(width)) << leftTitle << "    " << rightTitle << "\n";
    for (std::size_t i = 0; i < left.size(); ++i)
        out << "    " << std::setw(int(width)) << left[i] << "    " << right[i] << "\n";
    out << std::right;
}

std::string compositeName(const Pipeline<double>& p)
{
    if (p.convention == Convention::OpenGL)
        return "P * V";
    return p.projection == ProjectionKind::Perspective ? "N_per" : "N_par";
}

template <class T> Pipeline<T> pipelineFor(const Scene& scene)
{
    if constexpr (isExactScalar<T>)
        return exactPipeline(scene);
    else
        return withEffectStages(buildPipeline(castCamera<T>(scene.camera)), scene.effects);
}

Json countsJson(const ClipCounts& c)
{
    return {{"inside", c.inside}, {"clipped", c.clipped}, {"outside", c.outside}};
}

// What each listed effect found.
Json effectsJson(const Scene& scene, const EffectOutcomes& outcomes)
{
    const Pipeline<double> p = pipelineFor<double>(scene);
    Json out = Json::object();
    if (outcomes.clip)
        out["clip"] = {{"segments", countsJson(outcomes.clip->segments)},
                       {"polygons", countsJson(outcomes.clip->polygons)}};
    if (scene.effects.has(EffectKind::Divide)) {
        const bool added = divideAddsStage(p);
        out["divide"] = {{"stage", added ? Json(p.stages.back().symbol()) : Json(nullptr)},
                         {"note", added ? "appended after the last stage"
                                        : "a parallel view needs no divide: its canonical volume is already parallel"}};
    }
    if (outcomes.cull)
        out["cull"] = {{"faces", outcomes.cull->faces}, {"culled", outcomes.cull->culled}};
    if (outcomes.depth) {
        const DepthOutcome& d = *outcomes.depth;
        Json resolution = Json::array();
        for (const DepthSample& s : d.resolution)
            resolution.push_back({{"distance", s.distance}, {"step", s.step}, {"past_far", s.pastFar}});
        Json fights = Json::array();
        for (const auto& f : d.zFighting)
            fights.push_back({{"object", f[0]}, {"face", f[1]}, {"with_object", f[2]}, {"with_face", f[3]}});
        out["depth"] = {{"bits", d.options.bits},
                        {"format", d.options.floating ? "float" : "unorm"},
                        {"reversed", d.options.reversed},
                        {"resolution", resolution},
                        {"vertices", d.vertices},
                        {"distinct_values", d.distinctValues},
                        {"z_fighting", d.zFightingChecked ? fights : Json(nullptr)}};
    }
    if (outcomes.raster) {
        const RasterOutcome& r = *outcomes.raster;
        std::set<std::pair<int, int>> faces;
        for (std::size_t i = 0; i < r.object.size(); ++i)
            if (r.object[i] >= 0)
                faces.insert({r.object[i], r.face[i]});
        out["raster"] = {{"width", r.width}, {"height", r.height}, {"covered_pixels", r.covered},
                         {"visible_faces", faces.size()}};
    }
    return out;
}

template <class F> auto withPrecision(const PrecisionChoice& precision, F&& f)
{
    switch (precision.type) {
    case Precision::Float: return f(float{});
    case Precision::LongDouble: return f(static_cast<long double>(0));
#ifdef VIEWPIPE_WIDE_SCALARS
    case Precision::Float128: return f(Float128{});
    case Precision::Mpfr: setReferenceBits(precision.mpfrBits); return f(Mpfr{});
#else
    case Precision::Float128:
    case Precision::Mpfr:
        throw InputError("--precision", precisionName(precision) + " is computed by the app and the CLI, not in the browser");
#endif
    case Precision::Exact: return f(Exact{});
    case Precision::Double: break;
    }
    return f(double{});
}

// "foley", or the camera's API: "opengl", "direct3d", ...
template <class T> std::string conventionName(const Pipeline<T>& p)
{
    return p.convention == Convention::Foley ? "foley" : gl::apiName(p.api);
}

} // namespace

PrecisionChoice parsePrecision(const std::string& name, unsigned mpfrBits)
{
    static const std::map<std::string, Precision> names = {{"float", Precision::Float},
                                                           {"double", Precision::Double},
                                                           {"long-double", Precision::LongDouble},
                                                           {"float128", Precision::Float128},
                                                           {"mpfr", Precision::Mpfr},
                                                           {"exact", Precision::Exact}};
    const auto found = names.find(name);
    if (found == names.end())
        throw InputError("--precision", "must be float, double, long-double, float128, mpfr or exact (got \"" + name + "\")");
    if (mpfrBits < 16 || mpfrBits > 4096)
        throw InputError("--bits", "must be 16 to 4096 (got " + std::to_string(mpfrBits) + ")");
    return {found->second, mpfrBits};
}

std::string precisionName(const PrecisionChoice& precision)
{
    static const char* names[] = {"float", "double", "long-double", "float128", "mpfr", "exact"};
    const std::string name = names[static_cast<int>(precision.type)];
    return precision.type == Precision::Mpfr ? name + "-" + std::to_string(precision.mpfrBits) : name;
}

Json pipelineJson(const Scene& scene, const PrecisionChoice& precision, const EffectOutcomes& outcomes)
{
    return withPrecision(precision, [&](auto zero) {
        using T = decltype(zero);
        const Pipeline<T> p = pipelineFor<T>(scene);
        const std::vector<Mat4<T>> cumulative = cumulativeProducts(p.stages);
        Json out = {{"convention", conventionName(p)},
                    {"projection", projectionName(p.projection)},
                    {"precision", precisionName(precision)}};
        Json stages = Json::array();
        for (std::size_t k = 0; k < p.stages.size(); ++k)
        {
            stages.push_back({{"symbol", p.stages[k].symbol()},
                              {"explanation", mathPlainText(p.stages[k].explanation)},
                              {"matrix", matrixJson(p.stages[k].matrix)},
                              {"cumulative", matrixJson(cumulative[k])}});
            if (p.stages[k].divides()) // no matrix: "matrix" is the identity, which leaves products unchanged
                stages.back()["divides"] = kDivideMapping;
        }
        out["stages"] = stages;
        out["composite"] = matrixJson(p.composite);
        if (p.zmin)
            out["zmin"] = number(*p.zmin);
        if (p.view)
            out["view"] = matrixJson(*p.view);
        if (p.projectionMatrix) {
            out["projection_matrix"] = matrixJson(*p.projectionMatrix);
            const auto& camera = std::get<gl::Camera<double>>(scene.camera);
            out["handedness"] = gl::handednessName(camera.handedness);
            out["depth"] = gl::depthModeName(camera.depth);
            out["api_matrix"] = matrixJson(gl::asDocumented(*p.projectionMatrix, p.api));
            out["api_matrix_vectors"] = gl::rowVectors(p.api) ? "row" : "column";
            Json order = Json::array();
            for (const T& x : gl::memoryOrder(*p.projectionMatrix))
                order.push_back(number(x));
            out["memory_order"] = order;
            out["memory_order_library"] = gl::memoryOrderLibrary(p.api);
        }
        if (!scene.effects.empty())
            out["effects"] = effectsJson(scene, outcomes);
        if constexpr (isExactScalar<T>) {
            Json inexact = Json::array();
            Json exactStages = Json::array();
            for (std::size_t k = 0; k < p.stages.size(); ++k) {
                exactStages.push_back({{"symbol", p.stages[k].symbol()},
                                       {"matrix", exactJson(p.stages[k].matrix,
                                                            "exact.stages[" + std::to_string(k) + "].matrix", inexact)}});
                if (p.stages[k].divides())
                    exactStages.back()["divides"] = kDivideMapping;
            }
            out["exact"] = {{"stages", exactStages},
                            {"composite", exactJson(p.composite, "exact.composite", inexact)},
                            {"zmin", p.zmin ? Json(p.zmin->text()) : Json(nullptr)}};
            if (p.zmin && !p.zmin->isExact())
                inexact.push_back({{"path", "exact.zmin"}, {"reason", p.zmin->inexactReason()}});
            if (!inexact.empty())
                out["inexact"] = inexact;
        }
        return out;
    });
}

void printPipeline(std::ostream& out, const Scene& scene, const PrecisionChoice& precision,
                   const EffectOutcomes& outcomes)
{
    withPrecision(precision, [&](auto zero) {
        using T = decltype(zero);
        const Pipeline<T> p = pipelineFor<T>(scene);
        const Pipeline<double> names = pipelineFor<double>(scene);
        const std::vector<Mat4<T>> cumulative = cumulativeProducts(p.stages);
        out << scene.name << ": " << (p.convention == Convention::Foley ? "Foley" : gl::apiTitle(p.api)) << ", "
            << projectionName(p.projection) << ", " << precisionName(precision) << " precision\n"
            << "Column vectors: p' = M p. Each stage's matrix, and the product of all stages so far.\n\n";
        std::string product;
        for (std::size_t k = 0; k < p.stages.size(); ++k) {
            const Stage<T>& stage = p.stages[k];
            out << k + 1 << ". " << stage.symbol() << " - " << mathPlainText(stage.explanation) << "\n"; // the symbols as scripts use them
            if (stage.divides()) { // not a matrix, and no factor of the product
                out << "    " << kDivideMapping << ", not a matrix\n\n";
                continue;
            }
            printSideBySide(out, matrixLines(stage.matrix), matrixLines(cumulative[k]), stage.symbol(),
                            "cumulative");
            out << "\n";
            product = stage.symbol() + (product.empty() ? "" : " * " + product);
        }
        out << compositeName(names) << " = " << product << "\n";
        for (const std::string& line : matrixLines(p.composite))
            out << "    " << line << "\n";
        if (p.zmin)
            out << "\nz_min = " << shortNumber(*p.zmin)
                << "  (canonical perspective volume: x = +-z, y = +-z, z = z_min, z = -1)\n";
        if constexpr (isExactScalar<T>) {
            std::set<std::string> reasons;
            for (const Stage<T>& stage : p.stages)
                for (const T& x : stage.matrix.reshaped())
                    if (!x.isExact())
                        reasons.insert(x.inexactReason());
            for (const std::string& reason : reasons)
                out << "\n~ not exact: " << reason << "; given to 6 digits here, 40 in --json\n";
        }
        if (p.view && p.projectionMatrix) {
            out << "\n";
            const auto& camera = std::get<gl::Camera<double>>(scene.camera);
            printSideBySide(out, matrixLines(*p.view), matrixLines(*p.projectionMatrix),
                            "view (lookAt, " + gl::handednessName(camera.handedness) + "-handed)",
                            "projection (" + projectionName(p.projection) + ", " + gl::depthModeName(camera.depth) +
                                " depth)");
            if (gl::rowVectors(p.api)) {
                out << "\n    As " << gl::apiTitle(p.api) << "'s documentation writes it, for row vectors (p' = p M):\n";
                for (const std::string& line : matrixLines(gl::asDocumented(*p.projectionMatrix, p.api)))
                    out << "    " << line << "\n";
            }
            out << "\n    In memory (" << gl::memoryOrderLibrary(p.api) << "):\n    ";
            for (const T& x : gl::memoryOrder(*p.projectionMatrix))
                out << " " << shortNumber(x);
            out << "\n";
        }
        if (!scene.effects.empty()) {
            const Json effects = effectsJson(scene, outcomes);
            out << "\nEffects:\n";
            for (const auto& item : effects.items())
                out << "  " << item.key() << ": " << item.value().dump() << "\n";
        }
        return 0;
    });
}

Json traceJson(const Scene& scene, const Vec3<Exact>& typed, const PrecisionChoice& precision)
{
    // The verdict is the scene's and the point's as typed, whatever precision computes the numbers.
    const Pipeline<Exact> exact = pipelineFor<Exact>(scene);
    const PointTrace<Exact> exactTrace = tracePoint(exact, typed);
    const ClipVerdict verdict = clipVerdict(exactTrace.clip, exact.clipVolume);
    return withPrecision(precision, [&](auto zero) {
        using T = decltype(zero);
        const Vec3<T> point(scalarOf<T>(typed.x()), scalarOf<T>(typed.y()), scalarOf<T>(typed.z()));
        Pipeline<T> p;
        PointTrace<T> trace;
        if constexpr (isExactScalar<T>) { // computed above for the verdict
            p = exact;
            trace = exactTrace;
        } else {
            p = pipelineFor<T>(scene);
            trace = tracePoint(p, point);
        }
        Json stages = Json::array();
        for (std::size_t k = 0; k < p.stages.size(); ++k)
            stages.push_back({{"symbol", p.stages[k].symbol()}, {"point", vectorJson(trace.afterStage[k])}});
        Json out{{"convention", conventionName(p)},
                 {"projection", projectionName(p.projection)},
                 {"precision", precisionName(precision)},
                 {"point", vectorJson(point)},
                 {"stages", stages},
                 {"clip", vectorJson(trace.clip)},
                 {"divided", trace.divided ? vectorJson(*trace.divided) : Json(nullptr)},
                 {"inside", verdict.inside},
                 {"on_planes", verdict.behindEye ? std::vector<std::string>{} : planeNames(verdict.on, p.convention)}};
        if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>) {
            // A coordinate the type cannot hold is computed rounded; the verdict is still the typed point's.
            for (int i = 0; i < 3; ++i)
                if (Exact(double(point[i])) != typed[i])
                    out["rounded"] = true;
        }
        if constexpr (isExactScalar<T>) {
            Json exactStages = Json::array();
            for (std::size_t k = 0; k < p.stages.size(); ++k)
                exactStages.push_back({{"symbol", p.stages[k].symbol()}, {"point", exactJson(trace.afterStage[k])}});
            out["exact"] = {{"point", exactJson(typed)},
                            {"stages", exactStages},
                            {"clip", exactJson(trace.clip)},
                            {"divided", trace.divided ? exactJson(*trace.divided) : Json(nullptr)}};
        }
        if (scene.effects.has(EffectKind::Clip)) {
            // Which clipping planes reject the point, decided before any divide.
            out["clipping"] = {{"clipped", !verdict.inside},
                               {"behind_eye", verdict.behindEye},
                               {"outside_planes", verdict.behindEye ? std::vector<std::string>{}
                                                                    : planeNames(verdict.outside, p.convention)}};
        }
        return out;
    });
}

Json apiTraceJson(const Scene& scene, const Vec3<double>& point, const std::string& apiChoice, int width, int height)
{
    std::optional<gl::Api> only;
    std::string known = "\"all\"";
    for (const gl::Api api : gl::kApis) {
        known += ", \"" + gl::apiName(api) + "\"";
        if (apiChoice == gl::apiName(api))
            only = api;
    }
    if (!only && apiChoice != "all")
        throw InputError("--api", "must be one of " + known + " (got \"" + apiChoice + "\")");
    const gl::Camera<double>& camera = lookAtCamera(scene, "API conventions");
    Json rows = Json::array();
    for (const gl::Api api : gl::kApis)
        for (const gl::Handedness handedness : {gl::Handedness::Right, gl::Handedness::Left})
            for (const gl::DepthMode depth : {gl::DepthMode::Standard, gl::DepthMode::Reversed}) {
                if (only && api != *only)
                    continue;
                gl::Camera<double> variant = camera;
                variant.api = api;
                variant.handedness = handedness;
                variant.depth = depth;
                // Stage by stage, as `trace` goes: a point on the eye plane gets w = 0 exactly.
                const PointTrace<double> trace = tracePoint(buildPipeline(variant), point);
                Json row = {{"api", gl::apiName(api)},
                            {"handedness", gl::handednessName(handedness)},
                            {"depth", gl::depthModeName(depth)},
                            {"clip", vectorJson(trace.clip)},
                            {"inside", trace.inside},
                            {"behind_eye", trace.clip.w() < 0},
                            {"window_origin", gl::windowOriginTopLeft(api) ? "top-left" : "bottom-left"}};
                if (trace.divided) {
                    row["ndc"] = vectorJson(*trace.divided);
                    row["window"] = vectorJson(gl::windowCoordinates(api, *trace.divided, width, height));
                } else {
                    row["ndc"] = row["window"] = nullptr;
                }
                rows.push_back(row);
            }
    return {{"point", vectorJson(point)}, {"viewport", {width, height}}, {"rows", rows}};
}

void printApiTrace(std::ostream& out, const Scene& scene, const Vec3<double>& point, const std::string& api,
                   int width, int height)
{
    const Json t = apiTraceJson(scene, point, api, width, height);
    auto show = [](const Json& v) {
        if (v.is_null())
            return std::string("none (w = 0)");
        std::string s = "(";
        for (std::size_t i = 0; i < v.size(); ++i)
            s += (i ? ", " : "") + shortNumber(v[i].get<double>());
        return s + ")";
    };
    out << "Point " << show(t["point"]) << " through the camera of \"" << scene.name
        << "\" under each API's conventions, the same numbers in every row.\n"
        << "Window coordinates: a " << width << " x " << height
        << " viewport at (0, 0), depth range [0, 1]; the origin as each API puts it.\n\n";
    std::vector<std::array<std::string, 8>> table = {
        {"api", "hand", "depth", "clip (x, y, z, w)", "NDC (x, y, z)", "window (x, y, z)", "origin", ""}};
    for (const Json& row : t["rows"])
        table.push_back({gl::apiTitle(gl::apiNamed(row["api"], "api")), row["handedness"], row["depth"],
                         show(row["clip"]), show(row["ndc"]), show(row["window"]), row["window_origin"],
                         row["behind_eye"].get<bool>() ? "behind the eye (w < 0): a false image"
                         : row["inside"].get<bool>()   ? "inside"
                                                       : "outside"});
    std::array<std::size_t, 8> widths{};
    for (const auto& line : table)
        for (std::size_t c = 0; c < line.size(); ++c)
            widths[c] = std::max(widths[c], line[c].size());
    for (const auto& line : table) {
        std::string text;
        for (std::size_t c = 0; c < line.size(); ++c)
            text += line[c] + std::string(c + 1 < line.size() ? widths[c] - line[c].size() + 2 : 0, ' ');
        out << text.substr(0, text.find_last_not_of(' ') + 1) << "\n";
    }
    out << "\nLeft-handed rows take the same numbers through lookAtLH: the picture is mirrored left to right.\n"
           "Reversed rows exchange near and far: window z becomes 1 - z.";
    const bool vulkan = std::any_of(t["rows"].begin(), t["rows"].end(), [](const Json& row) { return row["api"] == "vulkan"; });
    out << (vulkan ? " Vulkan's clip y is negated and its window y runs down, so the point lands where Direct3D, "
                     "Metal and WebGPU put it."
                   : "")
        << "\n";
}

// "inside the canonical view volume", or on which face, edge or corner of it.
std::string verdictText(const Json& trace)
{
    const Json& on = trace["on_planes"];
    if (!trace["inside"].get<bool>())
        return "outside the canonical view volume";
    if (on.empty())
        return "inside the canonical view volume";
    std::string faces;
    for (std::size_t i = 0; i < on.size(); ++i)
        faces += (i == 0 ? "" : i + 1 == on.size() ? " and " : ", ") + on[i].get<std::string>();
    const char* where[] = {"", "on the ", "on the edge of the ", "on the corner of the "};
    return where[std::min<std::size_t>(on.size(), 3)] + faces + (on.size() == 1 ? " face" : " faces") +
           " of the canonical view volume (inside)";
}

void printTrace(std::ostream& out, const Scene& scene, const Vec3<Exact>& point, const PrecisionChoice& precision)
{
    // w's sign from its number, or from the decimal a wide precision writes; never from an exact
    // expression's first term ("-64/5 + 48*sqrt(2)/5" is positive): traceJson gives it as a number too.
    const auto behindTheEye = [](const Json& w) { return w.is_string() ? w.get<std::string>().front() == '-' : w.get<double>() < 0; };
    const Json t = traceJson(scene, point, precision);
    const Json& numbers = t.contains("exact") ? t["exact"] : t; // exact values as they are
    auto show = [](const Json& v) {
        std::string s = "(";
        for (std::size_t i = 0; i < v.size(); ++i)
            s += (i ? ", " : "") + (v[i].is_string() ? v[i].get<std::string>() : shortNumber(v[i].get<double>()));
        return s + ")";
    };
    out << "Point " << show(numbers["point"]) << " through " << scene.name << " ("
        << t["projection"].get<std::string>() << ", " << precisionName(precision) << " precision), homogeneous (x, y, z, w):\n";
    if (t.contains("rounded")) {
        std::string rounded;
        for (const Json& x : t["point"])
            rounded += (rounded.empty() ? "" : ", ") + formatSignificant(x.get<double>(), 20);
        out << "  (computed from the nearest " << precisionName(precision) << " values, (" << rounded
            << "); the verdict is the point's as typed)\n";
    }
    std::size_t width = 0;
    for (const Json& stage : numbers["stages"])
        width = std::max(width, stage["symbol"].get<std::string>().size());
    for (const Json& stage : numbers["stages"])
        out << "  after " << std::left << std::setw(int(width)) << stage["symbol"].get<std::string>() << std::right
            << "  " << show(stage["point"]) << "\n";
    const bool foleyPerspective = t["convention"] == "foley" && t["projection"] == "perspective";
    out << "  before the divide" << (foleyPerspective ? " (after Foley's M)" : "") << ": " << show(numbers["clip"]) << "\n";
    if (numbers["divided"].is_null())
        out << "  divide: w = 0, the point lies on the eye plane and has no image\n";
    else
        out << "  after the divide: " << show(numbers["divided"])
            << (behindTheEye(t["clip"].back()) ? "  (w < 0: behind the eye, a false image)" : "") << "\n";
    out << "  " << verdictText(t) << "\n";
    if (t.contains("clipping")) {
        const Json& c = t["clipping"];
        out << "  clip: " << (c["clipped"].get<bool>() ? "clipped away" : "kept");
        if (c["behind_eye"].get<bool>())
            out << ", behind the eye (w <= 0)";
        for (const Json& plane : c["outside_planes"])
            out << ", outside the " << plane.get<std::string>() << " plane";
        out << "\n";
    }
}

Json classifyJson(const Scene& scene)
{
    const Classification c = classify(scene.camera);
    static const char* axes[] = {"x", "y", "z"};
    Json points = Json::array();
    for (const VanishingPoint& vp : c.vanishingPoints)
        points.push_back({{"axis", axes[vp.axis]},
                          {"world", {vp.world.x(), vp.world.y(), vp.world.z()}},
                          {"image", {vp.image.x(), vp.image.y()}}});
    return {{"projection", projectionName(c.projection)},
            {"family", c.family},
            {"kind", c.kind},
            {"description", c.description},
            {"foreshortening", c.foreshortening ? Json(*c.foreshortening) : Json(nullptr)},
            {"alpha_deg", c.alphaDegrees ? Json(*c.alphaDegrees) : Json(nullptr)},
            {"vanishing_points", points}};
}

void printClassification(std::ostream& out, const Scene& scene)
{
    const Classification c = classify(scene.camera);
    static const char* axes[] = {"x", "y", "z"};
    out << c.description << "\n";
    if (c.foreshortening)
        out << "foreshortening: x " << shortNumber((*c.foreshortening)[0]) << ", y "
            << shortNumber((*c.foreshortening)[1]) << ", z " << shortNumber((*c.foreshortening)[2]) << "\n";
    if (c.projection == ProjectionKind::Perspective) {
        out << "vanishing points (" << c.vanishingPoints.size() << " finite):\n";
        for (const VanishingPoint& vp : c.vanishingPoints)
            out << "  " << axes[vp.axis] << ": world (" << shortNumber(vp.world.x()) << ", " << shortNumber(vp.world.y())
                << ", " << shortNumber(vp.world.z()) << "), picture (" << shortNumber(vp.image.x()) << ", "
                << shortNumber(vp.image.y()) << ")\n";
        for (int axis = 0; axis < 3; ++axis)
            if (std::none_of(c.vanishingPoints.begin(), c.vanishingPoints.end(),
                             [axis](const VanishingPoint& vp) { return vp.axis == axis; }))
                out << "  " << axes[axis] << ": none (parallel to the view plane: such lines stay parallel)\n";
    }
}

} // namespace viewpipe::report

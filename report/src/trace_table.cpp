#include "viewpipe/report/trace_table.hpp"

#include "viewpipe/format.hpp"
#include "viewpipe/stage_kind.hpp"

namespace viewpipe::report {

std::string tableCell(double x, const Exact* exact)
{
    if (exact && exact->readsExactly())
        return "$" + exact->latex() + "$";
    std::string text;
    for (char c : formatSignificant(x, 5)) // as the pictures set numbers: 1.5e−07 too
        text += c == '-' ? std::string("\u2212") : std::string(1, c);
    return text;
}

TraceTable traceTable(const Pipeline<double>& pipeline, const Pipeline<Exact>* exact, const Vec3<double>& point,
                      int lastRow)
{
    const PointTrace<double> t = tracePoint(pipeline, point);
    const Vec4<Exact> world(fromDecimal<Exact>(point.x()), fromDecimal<Exact>(point.y()), fromDecimal<Exact>(point.z()),
                            Exact(1));
    std::optional<PointTrace<Exact>> e;
    if (exact)
        e = tracePoint(*exact, Vec3<Exact>(world.head<3>()));
    TraceTable table;
    auto row = [&table](std::string stage, const Vec4<double>& p, const Vec4<Exact>* q) {
        TraceTable::Row& r = table.rows.emplace_back();
        r.stage = std::move(stage);
        for (int k = 0; k < 4; ++k)
            r.cells[std::size_t(k)] = tableCell(p[k], q ? &(*q)[k] : nullptr);
    };
    row("world", point.homogeneous(), e ? &world : nullptr);
    for (std::size_t k = 0; k < pipeline.stages.size() && int(k) < lastRow; ++k)
        row("$" + stageSymbolMath(pipeline.stages[k].kind) + "$", t.afterStage[k], e ? &e->afterStage[k] : nullptr);
    if (lastRow < int(pipeline.stages.size()))
        return table;
    if (t.divided) {
        const Vec3<Exact>* d = e && e->divided ? &*e->divided : nullptr;
        table.verdict = "After the divide: (" + tableCell(t.divided->x(), d ? &d->x() : nullptr) + ", " +
                        tableCell(t.divided->y(), d ? &d->y() : nullptr) + ", " + tableCell(t.divided->z(), d ? &d->z() : nullptr) +
                        "); ";
    }
    const bool inside = e ? e->inside : t.inside; // decided exactly where the exact pipeline is at hand
    table.verdict += inside ? "inside the canonical volume." : "outside the canonical volume.";
    return table;
}

} // namespace viewpipe::report

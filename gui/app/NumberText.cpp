#include "NumberText.h"

#include <QCoreApplication>

#include <charconv>
#include <cmath>
#include <cstring>

#include "viewpipe/format.hpp"

namespace viewpipe::gui {

QString numberText(double value)
{
    if (std::isinf(value))
        return value > 0 ? "infinity" : "-infinity";
    return QString::fromStdString(formatShortest(value));
}

QString readNumber(const QString& text, bool infinityAllowed, double& value)
{
    const QString trimmed = text.trimmed();
    const QByteArray bytes = trimmed.toUtf8();
    const char* first = bytes.constData();
    const char* last = first + bytes.size();
    if (first == last)
        return QCoreApplication::translate("NumberText", "is empty: a number is needed");
    if (*first == '+' && last - first > 1 && first[1] != '+' && first[1] != '-')
        ++first; // from_chars takes no plus sign
    const auto [end, error] = std::from_chars(first, last, value);
    const QString quoted = "\"" + trimmed + "\"";
    if (error == std::errc::result_out_of_range)
        return QCoreApplication::translate("NumberText", "%1 is out of the range of a double").arg(quoted);
    if (error != std::errc() || end != last)
        return trimmed.contains(',') ? QCoreApplication::translate("NumberText", "%1 is not a number (the decimal point is '.')").arg(quoted)
               : infinityAllowed     ? QCoreApplication::translate("NumberText", "%1 is not a number or infinity").arg(quoted)
                                     : QCoreApplication::translate("NumberText", "%1 is not a number").arg(quoted);
    if (std::isnan(value) || (std::isinf(value) && !infinityAllowed))
        return QCoreApplication::translate("NumberText", "%1 is not a finite number").arg(quoted);
    return {};
}

bool sameBits(double a, double b)
{
    return std::memcmp(&a, &b, sizeof a) == 0;
}

} // namespace viewpipe::gui

#pragma once

#include <QString>
#include <qcustomplot.h>

namespace footpath {

/// What is wrong with a legend as drawn (call after a replot): an item narrower or lower than its
/// text needs (clipped: "Foot patl"), an item outside the legend, or a legend over a row's data.
/// Empty when all is well.
inline QString legendProblem(QCustomPlot* plot, QCPLegend* legend)
{
    for (int i = 0; i < legend->itemCount(); ++i) {
        QCPAbstractLegendItem* item = legend->item(i);
        if (item == nullptr)
            continue;
        const QSize needed = item->minimumOuterSizeHint();
        const QRect got = item->outerRect();
        const QString name = qobject_cast<QCPPlottableLegendItem*>(item)
                                 ? qobject_cast<QCPPlottableLegendItem*>(item)->plottable()->name()
                                 : QString::number(i);
        if (got.width() < needed.width() || got.height() < needed.height())
            return QStringLiteral("item '%1' is %2x%3 px, its text needs %4x%5 (legend %6 px wide, %7 columns)")
                .arg(name).arg(got.width()).arg(got.height()).arg(needed.width()).arg(needed.height())
                .arg(legend->outerRect().width()).arg(legend->columnCount());
        if (!plot->viewport().contains(got))
            return QStringLiteral("item '%1' lies outside the plot").arg(name);
    }
    for (QCPAxisRect* rect : plot->axisRects()) {
        if (rect->visible() && rect->layout() != nullptr && rect->rect().intersects(legend->outerRect()))
            return QStringLiteral("the legend covers a row's data");
    }
    return {};
}

}  // namespace footpath

#include "shared/Lineage.h"

#include "marbler/Colourways.h"
#include "marbler/GenomeIO.h"

#include <QCoreApplication>

#include <optional>

namespace marbler::ui {
namespace {

QString lineageText(const char* text) {
    return QCoreApplication::translate("Lineage", text);
}

} // namespace

QString operatorLabel(GeneticOperator op) {
    switch (op) {
    case GeneticOperator::Alter:
        return lineageText("Alter");
    case GeneticOperator::Recombine:
        return lineageText("Recombine");
    case GeneticOperator::Swap:
        return lineageText("Swap");
    case GeneticOperator::Reinit:
        return lineageText("Change initial state");
    }
    return {};
}

QString operatorLabel(const QString& name) {
    if (name == QLatin1String("wildcard")) return lineageText("Wildcard");
    const std::optional<GeneticOperator> op = parseOperator(name.toStdString());
    if (!op && name == QLatin1String(ColourwayOperator)) return lineageText("Colourway");
    return op ? operatorLabel(*op) : name;
}

QString LineageInfo::madeBy() const {
    if (op.isEmpty()) return QCoreApplication::translate("Lineage", "(not bred)");
    const QString label = operatorLabel(op);
    return varied ? QCoreApplication::translate("Lineage", "%1, varied").arg(label) : label;
}

LineageInfo lineageOf(const Genome& genome) {
    LineageInfo info;
    const Meta& meta = genome.meta;
    info.id = QString::fromStdString(meta.id ? *meta.id : genomeId(genome));
    if (meta.name) info.name = QString::fromStdString(*meta.name);
    if (meta.family) info.family = QString::fromStdString(*meta.family);
    if (meta.lineage) {
        const MetaLineage& lineage = *meta.lineage;
        if (lineage.op) info.op = QString::fromStdString(*lineage.op);
        if (lineage.parents)
            for (const std::string& p : *lineage.parents)
                info.parents << QString::fromStdString(p);
        if (lineage.generation) info.generation = *lineage.generation;
        info.varied = lineage.variation.has_value();
        if (lineage.change) info.change = QString::fromStdString(*lineage.change);
    }
    return info;
}

} // namespace marbler::ui

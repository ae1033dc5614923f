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
    if (op.isEmpty()) return lineageText("(not bred)");
    const QString label = operatorLabel(op);
    return varied ? lineageText("%1, varied").arg(label) : label;
}

LineageInfo lineageOf(const Genome& genome) {
    LineageInfo info;
    const auto& meta = genome.meta;
    if (meta.contains("id") && meta["id"].is_string())
        info.id = QString::fromStdString(meta["id"].get<std::string>());
    else
        info.id = QString::fromStdString(genomeId(genome));
    if (meta.contains("name") && meta["name"].is_string())
        info.name = QString::fromStdString(meta["name"].get<std::string>());
    if (meta.contains("family") && meta["family"].is_string())
        info.family = QString::fromStdString(meta["family"].get<std::string>());
    if (meta.contains("lineage") && meta["lineage"].is_object()) {
        const auto& lineage = meta["lineage"];
        if (lineage.contains("operator") && lineage["operator"].is_string())
            info.op = QString::fromStdString(lineage["operator"].get<std::string>());
        if (lineage.contains("parents") && lineage["parents"].is_array())
            for (const auto& p : lineage["parents"])
                if (p.is_string()) info.parents << QString::fromStdString(p.get<std::string>());
        if (lineage.contains("generation") && lineage["generation"].is_number_integer())
            info.generation = lineage["generation"].get<int>();
        info.varied = lineage.contains("variation") && lineage["variation"].is_object();
        if (lineage.contains("change") && lineage["change"].is_string())
            info.change = QString::fromStdString(lineage["change"].get<std::string>());
    }
    return info;
}

} // namespace marbler::ui

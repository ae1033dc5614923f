#pragma once
/// A design's lineage as the windows show it: how it was made (the operator in the window's
/// words), from which parents, in which generation, and its name. Read from the genome's meta.

#include "marbler/Genome.h"
#include "marbler/Operators.h"

#include <QString>
#include <QStringList>

namespace marbler::ui {

/// A short label of an operator for the UI ("Alter", "Recombine", "Swap", "Change initial state").
/// Files and the command line keep the operator names (alter, recombine, swap, reinit); the
/// window says only these labels.
QString operatorLabel(GeneticOperator op);
/// The label of an operator given by its file name ("reinit" -> "Change initial state"); an
/// unknown name is returned as it is.
QString operatorLabel(const QString& name);

/// The lineage of a design as the UI shows it, read from meta.lineage and meta.id.
struct LineageInfo {
    QString id;
    QString op;          ///< empty for a design that was not bred
    QStringList parents; ///< parent ids
    int generation = 0;
    QString name;        ///< meta.name when set
    QString family;      ///< meta.family: the pattern family it was drawn from (Families.h), kept by breeding
    bool varied = false; ///< a gentle variation of a result already in its generation
    QString change;      ///< what it changed from its home parent, in words (describeChange)

    /// The name the UI shows: meta.name, else the first 8 characters of the id.
    QString displayName() const { return name.isEmpty() ? id.left(8) : name; }
    /// How the design was made, in the window's words ("Change initial state", never "reinit";
    /// "Alter, varied"; "(not bred)").
    QString madeBy() const;
};
LineageInfo lineageOf(const Genome& genome);

} // namespace marbler::ui

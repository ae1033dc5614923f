#pragma once
/// The workbench's "New population" tool bar: the kind of a new random population (flat or
/// solid), its pattern family (Families.h, or mixed families), New random, and the object solid
/// designs are shown on. Owns the three boxes; the window reads them and hears of a new object.

#include <QObject>
#include <QString>

class QAction;
class QComboBox;
class QToolBar;

namespace marbler::ui {

class PopulationBar : public QObject {
    Q_OBJECT
public:
    /// Fills `bar`; `newRandom` is File ▸ New random population, shown among the boxes.
    PopulationBar(QToolBar* bar, QAction* newRandom);

    /// The kind chosen for a new random population: 2 (flat) or 3 (solid).
    int dimension() const;
    void setDimension(int dimension);
    /// See WorkbenchWindow::setPopulationFamily.
    QString family() const;
    void setFamily(const QString& family);
    /// The object solid designs are shown on; a name that is no object is ignored.
    QString mesh() const;
    void setMesh(const QString& mesh);

signals:
    /// The user (or setMesh) chose another object.
    void meshChanged(const QString& mesh);

private:
    /// The families of the chosen kind, keeping the chosen family where it is one of them.
    void fillFamilies();

    QComboBox* mDimension = nullptr;
    QComboBox* mFamily = nullptr; ///< "" for mixed families
    QComboBox* mMesh = nullptr;
};

} // namespace marbler::ui

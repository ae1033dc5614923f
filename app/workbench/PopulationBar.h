#pragma once
/// The workbench's "New population" tool bar: the kind of a new random population (flat or
/// solid), its pattern family (Families.h, or mixed families), New random, and the object the
/// grid's designs are shown on: for a solid population a built-in object or a mesh file, for a
/// flat one also none ("Flat", the default; an object shows the design on its texture
/// coordinates). Owns the three boxes; the window reads them and hears of a new object.

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
    /// The object solid designs are shown on: a built-in name, or a mesh file's path; a name
    /// that is neither is ignored.
    QString mesh() const { return mSolidMesh; }
    void setMesh(const QString& mesh);
    /// The object flat designs are shown on, as mesh(); empty: flat.
    QString flatMesh() const { return mFlatMesh; }
    void setFlatMesh(const QString& mesh);
    /// The kind of the population the grid shows (2 or 3): whose object the box shows and sets.
    void setShownKind(int dimension);
    int shownKind() const { return mShownKind; }
    /// The object box (tests).
    QComboBox* objectBox() const { return mMesh; }

signals:
    /// The user (or setMesh) chose another object for solid designs.
    void meshChanged(const QString& mesh);
    /// The user (or setFlatMesh) chose another object (or flat) for flat designs.
    void flatMeshChanged(const QString& mesh);

private:
    /// The families of the chosen kind, keeping the chosen family where it is one of them.
    void fillFamilies();
    /// The object box for the shown kind: "Flat" (flat only), the built-ins, the chosen file,
    /// "Mesh file…"; the shown kind's object selected.
    void fillObjects();
    /// The user picked entry `index` of the object box.
    void objectActivated(int index);
    /// Sets the object of a kind and says so when it changed.
    void setObject(int dimension, const QString& mesh);

    QComboBox* mDimension = nullptr;
    QComboBox* mFamily = nullptr; ///< "" for mixed families
    QComboBox* mMesh = nullptr;
    QString mSolidMesh, mFlatMesh;
    int mShownKind = 2;
};

} // namespace marbler::ui

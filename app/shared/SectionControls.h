#pragma once
/// The controls of a solid design's cross-section, in the editor's tool panel (EditorWindow.h)
/// and the large view (DesignDialog.h): the section shown (its axis or, turned, its normal typed
/// or set by the tilt and turn handles; where along it by a slider and a number) and, in the
/// editor, the object the design is shown on. They say what the user chose; the window sets the
/// section everywhere.

#include "marbler/Sampling.h"

#include <QString>
#include <QWidget>

#include <glm/vec3.hpp>

#include <functional>
#include <optional>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QSlider;

namespace marbler::ui {

class SectionControls : public QWidget {
    Q_OBJECT
public:
    /// Showing `slice` of a block whose size `size` tells (asked at each change); `withObject`:
    /// the object box too (the editor's panel; the large view has its own object).
    SectionControls(std::function<glm::dvec3()> size, const Slice& slice, QWidget* parent = nullptr,
                    bool withObject = true);
    /// Shows `slice` in the axis box, the slider and the number, whichever moved it (no
    /// sliceChosen follows).
    void showSlice(const Slice& slice);

signals:
    /// The user moved the section.
    void sliceChosen(const marbler::Slice& slice);
    /// The user chose an object: a built-in mesh's name or a mesh file.
    void meshChosen(const QString& mesh);

private:
    void chooseMesh(int index);
    /// The section the widgets show now: the axis, or the typed or handled normal, and the
    /// position along it.
    Slice current() const;
    /// The normal the tilt and turn handles give (the axis turned by both).
    glm::dvec3 handledNormal() const;
    void normalTyped();
    void handlesMoved();

    std::function<glm::dvec3()> mSize;
    QComboBox* mAxis;
    QSlider* mPosition;
    QDoubleSpinBox* mValue;
    QComboBox* mMesh;
    QLineEdit* mNormal;
    QSlider* mTilt;
    QSlider* mTurn;
    QLabel* mNormalError;
    std::optional<glm::dvec3> mTurned; ///< the turned section's normal; none: across the axis
    bool mUpdating = false;            ///< the widgets are being set to a slice (no feedback)
};

} // namespace marbler::ui

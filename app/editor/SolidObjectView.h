#pragma once
/// The editor's view of a design on an object: a solid beside its cross-section, a flat design
/// (laid on the object's texture coordinates) beside the canvas (EditorWindow.h).

#include "marbler/Genome.h"
#include "marbler/Mesh.h"
#include "marbler/Sampling.h"
#include "shared/ViewController.h"

#include <QImage>
#include <QPointF>
#include <QRectF>
#include <QString>
#include <QWidget>

#include <cstdint>
#include <optional>

class QComboBox;
class QPainter;

namespace marbler::ui {

class RenderService;

/// A design on its object, turned by dragging (its angle kept in meta.view), the object chosen
/// from the built-ins or a mesh file. Rendered by the render service, coarse while turning; a
/// flat design only while the view is shown (it is optional beside a flat canvas).
class SolidObjectView : public QWidget {
    Q_OBJECT
public:
    SolidObjectView(RenderService* renderer, QWidget* parent = nullptr);
    ~SolidObjectView() override;
    void setDesign(const Genome& design);
    void setMesh(const QString& mesh);
    QString mesh() const { return mMesh; }
    /// Puts a box of objects in the view's corner (the built-ins and "Mesh file…"), for a flat
    /// design, whose editor has no section controls; the object chosen is remembered in the
    /// settings ("editor/flatMesh", the book at first).
    void offerObjects();
    /// The box offerObjects() made (null before).
    QComboBox* objectBox() const { return mObjects; }
    /// What the view says instead of an image ("Rendering…", why it cannot render); empty once
    /// an image is shown.
    QString message() const { return mMessage; }
    /// The cross-section the editor shows: drawn in the corner as a plane through the block.
    void setSlice(const Slice& slice);
    ViewAngle angle() const { return mAngle; }
    const QImage& image() const { return mImage; }
    /// Issue 23: where a solid's block and section plane are drawn, in the corner; dragging
    /// there turns the section (sliceTurned), not the object.
    QRectF sliceInset() const;

signals:
    /// The user turned the section by dragging its plane in the corner: horizontally about the
    /// block's y axis, vertically about its x axis, through the same point nearest the middle.
    void sliceTurned(const marbler::Slice& slice);

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void showEvent(QShowEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;

private:
    void request(bool previewOnly);
    void paintSlice(QPainter& p) const;
    RenderService* mRenderer;
    std::uint64_t mKey;
    Genome mDesign;
    QString mMesh = QString::fromLatin1(DefaultMesh);
    ViewAngle mAngle;
    QImage mImage;
    QPointF mLast;
    bool mTurning = false;
    bool mTurningSlice = false; ///< a drag in the corner's inset turns the section
    bool mAngleSet = false;     ///< the angle was taken from the first design
    std::optional<Slice> mSlice;
    QComboBox* mObjects = nullptr;
    QString mMessage;
};

} // namespace marbler::ui

#pragma once
/// The editor's view of a solid design on its object (EditorWindow.h shows it beside the
/// cross-section).

#include "marbler/Genome.h"
#include "marbler/Mesh.h"
#include "marbler/Sampling.h"
#include "shared/ViewController.h"

#include <QImage>
#include <QPointF>
#include <QString>
#include <QWidget>

#include <cstdint>
#include <optional>

class QPainter;

namespace marbler::ui {

class RenderService;

/// A solid design on its object, turned by dragging (its angle kept in meta.view), the object
/// chosen from the built-ins or a mesh file. Rendered by the render service, coarse while
/// turning.
class SolidObjectView : public QWidget {
    Q_OBJECT
public:
    SolidObjectView(RenderService* renderer, QWidget* parent = nullptr);
    ~SolidObjectView() override;
    void setDesign(const Genome& design);
    void setMesh(const QString& mesh);
    QString mesh() const { return mMesh; }
    /// The cross-section the editor shows: drawn in the corner as a plane through the block.
    void setSlice(const Slice& slice);
    ViewAngle angle() const { return mAngle; }
    const QImage& image() const { return mImage; }

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
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
    std::optional<Slice> mSlice;
};

} // namespace marbler::ui

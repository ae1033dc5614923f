#pragma once
/// The editor's live canvas: the design drawn at any zoom (re-rendered for the part in view,
/// never scaled up), the current tool's gestures with a preview while dragging, handles that
/// move the selected step, and the ink picker. It knows no document: it shows the design it is
/// given and says what the user did through its signals; the editor window applies them.

#include "editor/CanvasImage.h"
#include "editor/Gestures.h"
#include "shared/RenderService.h"
#include "shared/ViewController.h"

#include "marbler/Sampling.h"

#include <QElapsedTimer>
#include <QImage>
#include <QPointF>
#include <QSizeF>
#include <QString>
#include <QWidget>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace marbler::ui {

class EditorCanvas : public QWidget {
    Q_OBJECT
public:
    explicit EditorCanvas(RenderService* renderer, QWidget* parent = nullptr);
    ~EditorCanvas() override;

    /// What to draw (muted steps already left out); re-renders, coarse then antialiased (coarse
    /// only while dragging).
    void setDesign(const Genome& rendered);
    const Genome& design() const { return mDesign; }
    /// While a parameter is dragged elsewhere: coarse passes only; sharp again when set back.
    void setDragging(bool on);
    bool dragging() const { return mDragging; }
    void setTool(EditorTool tool);
    EditorTool tool() const { return mTool; }
    void setToolSettings(const ToolSettings& settings);
    const ToolSettings& toolSettings() const { return mSettings; }
    /// Shows the handles of that step of the drawn design (its centre or origin, its direction,
    /// its radius); none with nullopt.
    void setHandlesFor(std::optional<std::size_t> renderedIndex);
    /// Solids: the cross-section shown, and the plane clicks land on.
    void setSlice(const Slice& slice);
    Slice slice() const { return mSlice; }
    /// Pan (middle or right drag, or Space and drag), wheel zoom, 0 fits, 1 one to one, + and -.
    ViewController& view() { return mView; }

    /// The design point under a canvas point (widget coordinates); for a solid, on the slice.
    glm::dvec3 toDesign(QPointF widgetPoint) const;
    /// The widget point of a design point (of a solid, projected on the slice's plane).
    QPointF toWidget(const glm::dvec3& designPoint) const;

    /// The handles of the selected step, for tests and the overlay: where each is (widget). A
    /// stylus's handles are the points of its path, in order.
    /// Axis: a solid's circle, sphere, vortex or column, its axis tilted from the section's normal
    /// (at half an arm from the centre when across the section, a whole arm and a half when in it).
    enum class Handle { Centre, Direction, Radius, PathPoint, Axis };
    std::vector<std::pair<Handle, QPointF>> handlePoints() const;

    /// The image shown now, whether it is the sharp final one, and the steps of the gesture in
    /// progress (tests).
    const QImage& image() const { return mShown.image; }
    bool imageFinal() const { return mShown.final; }
    const std::vector<Operation>& pendingSteps() const { return mPending; }
    /// The design points a free-hand drag (stylus) has passed through so far, and the pen's
    /// pressure at each (1 for a mouse); empty when none is being drawn.
    const std::vector<glm::dvec3>& strokePoints() const { return mStroke; }
    /// The fraction of the view's pixels a free-hand stroke's live preview is rendered at, chosen
    /// from the time the last previews took so the preview keeps up with the pointer.
    double strokePreviewScale() const { return mPreviewScale; }
    /// A caption drawn at the canvas's top left (the compare panes say which state each shows:
    /// "Step 12 of 40", "Now"); none when empty.
    void setCaption(const QString& text);
    QString caption() const { return mCaption; }
    /// The repeat preview: the design shown tiled 3 × 3 about itself, plainly repeated or
    /// mirrored as the mirror repeat tile lays it (the tiles left and right mirrored across the
    /// vertical edges, those above and below across the horizontal ones), to judge the seams.
    /// Plain on a design whose bath wraps repeats it on its own lattice (straight, half-drop or
    /// brick; issue 29): the render of the plane three tiles a side about it.
    /// Turning it on or off fits the view (on: all nine tiles). Gestures still land on the
    /// design in the middle.
    enum class RepeatPreview { Off, Plain, Mirror };
    void setRepeatPreview(RepeatPreview mode);
    RepeatPreview repeatPreview() const { return mRepeat; }
    /// Whether the repeat preview shows the design on its wrap's lattice, rendered whole.
    bool tilesByLattice() const;
    /// Fits, zooms about the centre, one to one (the window's View menu and tool bar).
    void fitView();
    void zoomIn();
    void zoomOut();
    void oneToOne();

signals:
    /// A gesture made these steps (on release): one gesture, one undo step named `text`.
    void stepsMade(const std::vector<marbler::Operation>& ops, const QString& text);
    /// A handle moved the step (`final` on release; a drag is one undo step).
    void handleDragged(std::size_t renderedIndex, const marbler::Operation& op, bool final);
    /// The Pick tool clicked: the palette index seen there (-1: the bath) and the step that
    /// laid it.
    void inkPicked(int color, std::optional<std::size_t> renderedIndex);
    /// A gesture made nothing for a reason the user should hear (a stroke too long for a stylus).
    void gestureRefused(const QString& why);

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void keyReleaseEvent(QKeyEvent* event) override;
    /// A pen on a tablet: a stylus stroke takes its pressure; other tools get it as a mouse.
    void tabletEvent(QTabletEvent* event) override;

private:
    /// The 2D extent shown: the design, or its slice's plane.
    void updateDesignSize();
    /// The width and height of that extent, in design units.
    QSizeF planeSize() const;
    void drawCaption(QPainter& painter) const;
    /// `scale` < 1 renders fewer pixels over the same region (a free-hand stroke's live preview).
    void requestRender(const Genome& genome, bool previewOnly, double scale = 1.0);
    /// Whether the current tool draws a free-hand path.
    bool drawsPath() const;
    /// A tool's gesture from a mouse or a pen: press, move, release at a widget point.
    void beginGesture(QPointF widget, double pressure);
    void moveGesture(QPointF widget, double pressure);
    void endGesture(QPointF widget, double pressure);
    /// The steps the gesture in progress makes so far.
    std::vector<Operation> gestureSoFar() const;
    void rerender();
    void onRendered(std::uint64_t key, const QImage& image, bool final);
    void changeView();
    std::optional<Operation> selectedStep() const;
    /// The design with the selected step replaced by `op`.
    Genome withReplaced(const Operation& op) const;
    /// The step as a handle at `widget` would move it.
    Operation movedStep(Handle handle, QPointF widget) const;
    /// The plane coordinates of a design point, and back.
    QPointF toPlane(const glm::dvec3& p) const;
    glm::dvec3 fromPlane(QPointF plane) const;
    void drawOverlay(QPainter& painter) const;
    void drawStepOutline(QPainter& painter, const Operation& op) const;

    RenderService* mRenderer;
    std::uint64_t mKey;
    Genome mDesign;
    ViewController mView;
    Slice mSlice;
    bool mSliceChosen = false; ///< setSlice was called: a new design keeps the section chosen
    EditorTool mTool = Tool::Drop;
    ToolSettings mSettings;
    std::optional<std::size_t> mHandles;
    bool mDragging = false;
    QString mCaption;
    RepeatPreview mRepeat = RepeatPreview::Off;

    CanvasImage mShown;

    enum class Drag { None, Gesture, Pan, Handle };
    Drag mDrag = Drag::None;
    bool mSpace = false;
    QPointF mLastPos;
    glm::dvec3 mPress{0.0}, mCurrent{0.0};
    std::vector<Operation> mPending;
    Handle mHandle = Handle::Centre;
    std::size_t mHandleIndex = 0; ///< the path point a PathPoint handle moves

    std::vector<glm::dvec3> mStroke; ///< a free-hand drag's design points
    std::vector<double> mStrokePressure;
    bool mPenDown = false; ///< a tablet pen is drawing (its synthesised mouse events are ignored)
    /// A free-hand stroke's live preview: one render at a time (a newer request would abort the
    /// one being rendered, and a fast pointer would then never see one), the next asked for when
    /// it comes with the path as it is then, at a size that keeps each under PreviewTargetMs.
    bool mPreviewInFlight = false, mPreviewDirty = false;
    double mPreviewScale = 0.5;
    QElapsedTimer mPreviewClock;
};

} // namespace marbler::ui

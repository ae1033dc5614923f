#pragma once
/// One design of the grid: shows its image, its selection (a clear border and a check mark) and
/// takes clicks, keys, drags (turning a solid object) and dropped genome files.

#include "shared/GenomeClipboard.h"

#include <QImage>
#include <QPoint>
#include <QRect>
#include <QString>
#include <QStringList>
#include <QWidget>

namespace marbler::ui {

class DesignCell : public QWidget {
    Q_OBJECT
public:
    explicit DesignCell(int index, QWidget* parent = nullptr);

    int index() const { return mIndex; }
    /// What the cell shows; a null image with `hasDesign` shows "rendering".
    void setImage(const QImage& image);
    const QImage& image() const { return mImage; }
    void setHasDesign(bool hasDesign);
    void setSelectedParent(bool selected);
    bool isSelectedParent() const { return mSelected; }
    /// Whether dragging turns the object (solid designs).
    void setOrbitEnabled(bool enabled) { mOrbitEnabled = enabled; }
    /// A short caption drawn under the image (e.g. the operator that made the design).
    void setCaption(const QString& caption);
    const QString& caption() const { return mCaption; }
    /// What the design changed from its parent in words (meta.lineage.change), said first in the
    /// cell's tooltip; empty for a design that was not bred.
    void setChange(const QString& change);
    /// The user's note on the design (meta.note), said first in the cell's tooltip.
    void setNote(const QString& note);
    /// Whether the design has a lock: a padlock drawn at the caption's end (drawn, not a
    /// character, so it shows without an emoji font).
    void setLocked(bool locked);
    bool isLocked() const { return mLocked; }
    /// Where the padlock is drawn (empty when the cell shows none).
    QRect lockMarkerRect() const;
    /// A line drawn when rendering failed.
    void setError(const QString& message);
    /// That line (empty while the design renders or rendered).
    const QString& error() const { return mError; }

    QSize sizeHint() const override { return {240, 240}; }
    QSize minimumSizeHint() const override { return {96, 96}; }

signals:
    void clicked(int index);
    void openRequested(int index);
    void favouriteRequested(int index);
    /// F2: name the design.
    void renameRequested(int index);
    void contextMenuRequested(int index, const QPoint& globalPos);
    /// Arrow keys: move the focus by (dx, dy) cells.
    void focusMoveRequested(int index, int dx, int dy);
    /// The user dragged the object by a number of pixels; `finished` on release.
    void orbitDragged(int index, QPoint delta, bool finished);
    void filesDropped(int index, const QStringList& files);
    void genomeTextDropped(int index, const QByteArray& json);
    /// The cell's size changed (the window re-renders, debounced).
    void resized(int index);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void contextMenuEvent(QContextMenuEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void focusInEvent(QFocusEvent* event) override;
    void focusOutEvent(QFocusEvent* event) override;

private:
    void updateToolTip();

    int mIndex;
    QImage mImage;
    QString mCaption;
    QString mError;
    QString mChange;
    QString mNote;
    bool mHasDesign = false;
    bool mSelected = false;
    bool mLocked = false;
    bool mOrbitEnabled = false;
    bool mDragging = false;
    bool mSwallowRelease = false; ///< the release that ends a double-click is not a click
    QPoint mPressPos;
    QPoint mLastPos;
};

} // namespace marbler::ui

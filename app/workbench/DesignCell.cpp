#include "workbench/DesignCell.h"

#include <QApplication>
#include <QContextMenuEvent>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QKeyEvent>
#include <QMimeData>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QUrl>

#include <algorithm>

namespace marbler::ui {

DesignCell::DesignCell(int index, QWidget* parent)
    : QWidget(parent)
    , mIndex(index) {
    setFocusPolicy(Qt::StrongFocus);
    setAcceptDrops(true);
    setAttribute(Qt::WA_OpaquePaintEvent);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    setObjectName(QStringLiteral("cell%1").arg(index));
    setAccessibleName(tr("Design %1").arg(index + 1));
    setChange({});
}

void DesignCell::setChange(const QString& change) {
    mChange = change;
    updateToolTip();
}

void DesignCell::setNote(const QString& note) {
    mNote = note;
    updateToolTip();
}

void DesignCell::updateToolTip() {
    QString tip =
        tr("Click to choose as a parent, double-click to open large, F2 to rename, right-click for "
           "locks and favourites. Drop a genome file, or a PNG or TIFF Marbler exported, here to load it.");
    if (!mChange.isEmpty()) tip = tr("Changed: %1\n\n%2").arg(mChange, tip);
    if (!mNote.isEmpty()) tip = tr("Note: %1\n\n%2").arg(mNote, tip);
    setToolTip(tip);
}

void DesignCell::setImage(const QImage& image) {
    mImage = image;
    mError.clear();
    update();
}

void DesignCell::setHasDesign(bool hasDesign) {
    mHasDesign = hasDesign;
    if (!hasDesign) mImage = QImage();
    update();
}

void DesignCell::setSelectedParent(bool selected) {
    if (mSelected == selected) return;
    mSelected = selected;
    setAccessibleDescription(selected ? tr("selected as a parent") : QString());
    update();
}

void DesignCell::setCaption(const QString& caption) {
    mCaption = caption;
    update();
}

void DesignCell::setLocked(bool locked) {
    if (mLocked == locked) return;
    mLocked = locked;
    update();
}

namespace {
constexpr int CaptionHeight = 20;
}

QRect DesignCell::lockMarkerRect() const {
    if (!mLocked || !mHasDesign) return {};
    const QRect inner = rect().adjusted(6, 6, -6, -6);
    return {inner.right() - 6 - 14, inner.bottom() - CaptionHeight + 3, 14, 14};
}

/// A padlock: a body with a keyhole under a shackle, in the caption's colour.
static void drawPadlock(QPainter& p, const QRectF& box, const QColor& color) {
    p.save();
    p.setRenderHint(QPainter::Antialiasing);
    const qreal w = box.width(), h = box.height();
    const QRectF body(box.left(), box.top() + 0.45 * h, w, 0.55 * h);
    QPen pen(color, std::max<qreal>(1.5, w / 7.0));
    p.setPen(pen);
    p.setBrush(Qt::NoBrush);
    const QRectF shackle(box.left() + 0.22 * w, box.top(), 0.56 * w, 0.9 * h);
    p.drawArc(shackle, 0, 180 * 16);
    p.drawLine(QPointF(shackle.left(), shackle.center().y()), QPointF(shackle.left(), body.top()));
    p.drawLine(QPointF(shackle.right(), shackle.center().y()), QPointF(shackle.right(), body.top()));
    p.setPen(Qt::NoPen);
    p.setBrush(color);
    p.drawRoundedRect(body, 0.12 * w, 0.12 * w);
    p.setBrush(QColor(0, 0, 0, 160));
    p.drawEllipse(QPointF(body.center().x(), body.center().y() - 0.05 * h), 0.09 * w, 0.09 * w);
    p.restore();
}

void DesignCell::setError(const QString& message) {
    mError = message;
    update();
}

void DesignCell::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QColor base = palette().color(QPalette::Window).darker(115);
    p.fillRect(rect(), base);
    const QRect inner = rect().adjusted(6, 6, -6, -6);

    if (!mHasDesign) {
        p.setPen(palette().color(QPalette::PlaceholderText));
        p.drawText(inner, Qt::AlignCenter | Qt::TextWordWrap, tr("Empty\nopen or drop a design here"));
    } else if (!mImage.isNull()) {
        QSize s = mImage.size().scaled(inner.size(), Qt::KeepAspectRatio);
        QRect target(QPoint(0, 0), s);
        target.moveCenter(inner.center());
        p.setRenderHint(QPainter::SmoothPixmapTransform);
        p.drawImage(target, mImage);
    } else {
        p.setPen(palette().color(QPalette::PlaceholderText));
        p.drawText(inner, Qt::AlignCenter, mError.isEmpty() ? tr("rendering…") : QString());
    }
    if (!mError.isEmpty()) {
        p.setPen(QColor(0xc0, 0x30, 0x30));
        p.drawText(inner, Qt::AlignCenter | Qt::TextWordWrap, tr("Cannot render: %1").arg(mError));
    }
    if (!mCaption.isEmpty() && mHasDesign) {
        QFont f = font();
        f.setPointSizeF(f.pointSizeF() * 0.85);
        p.setFont(f);
        const QRect band(inner.left(), inner.bottom() - CaptionHeight, inner.width(), CaptionHeight);
        p.fillRect(band, QColor(0, 0, 0, 110));
        p.setPen(Qt::white);
        const QRect lock = lockMarkerRect();
        const QRect text = band.adjusted(6, 0, lock.isEmpty() ? -6 : -(lock.width() + 12), 0);
        p.drawText(text, Qt::AlignVCenter | Qt::AlignLeft,
                   p.fontMetrics().elidedText(mCaption, Qt::ElideRight, text.width()));
        if (!lock.isEmpty()) drawPadlock(p, lock, Qt::white);
    }

    if (mSelected) {
        // A parent must be obvious at a glance: a thick accent frame and a check badge.
        const QColor accent(0x2f, 0x80, 0xed);
        p.setPen(QPen(accent, 5));
        p.setBrush(Qt::NoBrush);
        p.drawRect(rect().adjusted(2, 2, -3, -3));
        const QRectF badge(width() - 38, 10, 28, 28);
        p.setPen(QPen(Qt::white, 2));
        p.setBrush(accent);
        p.drawEllipse(badge);
        QPainterPath tick;
        tick.moveTo(badge.left() + 7, badge.center().y() + 1);
        tick.lineTo(badge.left() + 12, badge.bottom() - 8);
        tick.lineTo(badge.right() - 6, badge.top() + 8);
        p.setPen(QPen(Qt::white, 3, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        p.setBrush(Qt::NoBrush);
        p.drawPath(tick);
    }
    if (hasFocus()) {
        p.setPen(QPen(palette().color(QPalette::Highlight), 2, Qt::DashLine));
        p.setBrush(Qt::NoBrush);
        p.drawRect(rect().adjusted(8, 8, -9, -9));
    }
}

void DesignCell::mousePressEvent(QMouseEvent* event) {
    if (event->button() != Qt::LeftButton) return QWidget::mousePressEvent(event);
    setFocus(Qt::MouseFocusReason);
    mPressPos = mLastPos = event->position().toPoint();
    mDragging = false;
}

void DesignCell::mouseMoveEvent(QMouseEvent* event) {
    if (!(event->buttons() & Qt::LeftButton) || !mOrbitEnabled) return;
    const QPoint pos = event->position().toPoint();
    if (!mDragging && (pos - mPressPos).manhattanLength() < QApplication::startDragDistance()) return;
    mDragging = true;
    emit orbitDragged(mIndex, pos - mLastPos, false);
    mLastPos = pos;
}

void DesignCell::mouseReleaseEvent(QMouseEvent* event) {
    if (event->button() != Qt::LeftButton) return QWidget::mouseReleaseEvent(event);
    if (mDragging) {
        mDragging = false;
        emit orbitDragged(mIndex, event->position().toPoint() - mLastPos, true);
        return;
    }
    if (mSwallowRelease) {
        mSwallowRelease = false;
        return;
    }
    if (rect().contains(event->position().toPoint())) emit clicked(mIndex);
}

void DesignCell::mouseDoubleClickEvent(QMouseEvent* event) {
    if (event->button() != Qt::LeftButton) return;
    // The first click of the pair already toggled the selection; undo that so a double-click
    // only opens the design.
    emit clicked(mIndex);
    mSwallowRelease = true;
    emit openRequested(mIndex);
}

void DesignCell::keyPressEvent(QKeyEvent* event) {
    switch (event->key()) {
    case Qt::Key_Left:
        emit focusMoveRequested(mIndex, -1, 0);
        break;
    case Qt::Key_Right:
        emit focusMoveRequested(mIndex, 1, 0);
        break;
    case Qt::Key_Up:
        emit focusMoveRequested(mIndex, 0, -1);
        break;
    case Qt::Key_Down:
        emit focusMoveRequested(mIndex, 0, 1);
        break;
    case Qt::Key_Space:
        emit clicked(mIndex);
        break;
    case Qt::Key_Return:
    case Qt::Key_Enter:
        emit openRequested(mIndex);
        break;
    case Qt::Key_F:
        emit favouriteRequested(mIndex);
        break;
    case Qt::Key_F2:
        if (mHasDesign) emit renameRequested(mIndex);
        break;
    case Qt::Key_Menu:
        emit contextMenuRequested(mIndex, mapToGlobal(rect().center()));
        break;
    default:
        QWidget::keyPressEvent(event);
        return;
    }
    event->accept();
}

void DesignCell::contextMenuEvent(QContextMenuEvent* event) {
    emit contextMenuRequested(mIndex, event->globalPos());
}

void DesignCell::dragEnterEvent(QDragEnterEvent* event) {
    const QMimeData* mime = event->mimeData();
    if (mime->hasFormat(QString::fromLatin1(GenomeMimeType)) || mime->hasUrls())
        event->acceptProposedAction();
}

void DesignCell::dropEvent(QDropEvent* event) {
    const QMimeData* mime = event->mimeData();
    if (mime->hasFormat(QString::fromLatin1(GenomeMimeType))) {
        emit genomeTextDropped(mIndex, mime->data(QString::fromLatin1(GenomeMimeType)));
    } else {
        QStringList files;
        for (const QUrl& url : mime->urls())
            if (url.isLocalFile()) files << url.toLocalFile();
        if (files.isEmpty()) return;
        emit filesDropped(mIndex, files);
    }
    event->acceptProposedAction();
}

void DesignCell::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    emit resized(mIndex);
}

void DesignCell::focusInEvent(QFocusEvent* event) {
    QWidget::focusInEvent(event);
    update();
}

void DesignCell::focusOutEvent(QFocusEvent* event) {
    QWidget::focusOutEvent(event);
    update();
}

} // namespace marbler::ui

#pragma once
/// One design shown large: save its genome, export an image at a chosen size, and (later) open
/// it in the editor.

#include "marbler/Genome.h"

#include <QDialog>
#include <QImage>

#include <cstdint>

class QLabel;

namespace marbler::ui {

class RenderService;

class DesignDialog : public QDialog {
    Q_OBJECT
public:
    DesignDialog(Genome genome, RenderService* renderer, const QString& mesh, QWidget* parent = nullptr);
    ~DesignDialog() override;

protected:
    void resizeEvent(QResizeEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;

private:
    void requestRender(bool previewOnly = false);
    void exportImage();

    Genome mGenome;
    RenderService* mRenderer;
    QString mMesh;
    std::uint64_t mKey;
    QLabel* mView = nullptr;
    QImage mImage;
    double mYaw = 30.0, mPitch = 20.0;
    QPoint mLastPos;
    bool mDragging = false;
};

/// Asks for a file name and saves the genome atomically; errors are reported. Returns success.
bool saveGenomeWithDialog(QWidget* parent, const Genome& genome);

} // namespace marbler::ui

#pragma once
/// The workbench's Lineage dock: the generation tree (branches included) with a thumbnail of
/// each design and a mosaic of each generation, rendered only for the rows in view. A click on a
/// design selects it in the grid; a double-click goes to a generation, or opens or brings back a
/// design (through the signals). Owns its dock, its tree, the thumbnails and what the user folded.

#include "workbench/PopulationModel.h"

#include <QCache>
#include <QHash>
#include <QImage>
#include <QMultiHash>
#include <QObject>
#include <QPixmap>
#include <QSet>
#include <QTimer>

#include <cstdint>
#include <functional>

class QDockWidget;
class QTreeWidget;
class QTreeWidgetItem;
class QWidget;

namespace marbler::ui {

class RenderService;

class LineagePanel : public QObject {
    Q_OBJECT
public:
    /// The icons: a design's thumbnail, and a generation's mosaic of nine (tiles of 14 pixels
    /// with 1-pixel gaps): small enough to render many, big enough to tell inks apart.
    static constexpr int IconSide = 44;
    /// Items of generations and designs hold the generation's history index in this role
    /// (column 0), items of designs their cell in CellRole, branch items their branch number
    /// in BranchRole.
    static constexpr int GenerationRole = Qt::UserRole;
    static constexpr int CellRole = Qt::UserRole + 1;
    static constexpr int BranchRole = Qt::UserRole + 2;

    /// `window` holds the dock and lends its palette; `mesh` says the object solid designs are
    /// shown on. The render service must outlive the panel.
    LineagePanel(QWidget* window, PopulationModel* model, RenderService* renderer,
                 std::function<QString()> mesh);
    ~LineagePanel() override;

    QDockWidget* dock() const { return mDock; }
    QTreeWidget* tree() const { return mTree; }
    /// Builds the tree anew from the model's history, keeping what the user folded.
    void update();
    /// Whether the lineage shows the rendered thumbnail of a design.
    bool hasThumbnail(const Genome& genome) const;

signals:
    /// A design of the current generation double-clicked: open it large.
    void openDesignRequested(int cell);
    /// A design of another generation double-clicked: bring it back into the grid.
    void bringBackRequested(int generation, int cell);

private:
    /// Fills a generation's item with its designs (done when it is first expanded).
    void populateGeneration(QTreeWidgetItem* item);
    void addDesign(QTreeWidgetItem* parent, int generation, int cell);
    /// Asks for the thumbnails of the items in view that are not rendered yet.
    void requestThumbnails();
    void requestThumbnail(const Genome& genome);
    QString thumbnailKey(const Genome& genome) const;
    /// The same key from what the model keeps of a design not in memory (issue 28).
    QString thumbnailKey(const CellInfo& info) const;
    /// A generation's icon: its nine thumbnails in a 3 x 3 mosaic (blanks until they arrive).
    QPixmap mosaic(int generation) const;
    QPixmap icon(const QString& key) const;
    void onThumbnail(std::uint64_t key, const QImage& image);
    /// A design clicked: selected in the grid, going to its generation first.
    void selectDesign(int generation, int cell);
    void onDoubleClicked(QTreeWidgetItem* item);

    QWidget* mWindow;
    PopulationModel* mModel;
    RenderService* mRenderer;
    std::function<QString()> mMesh;
    QDockWidget* mDock = nullptr;
    QTreeWidget* mTree = nullptr;
    /// Thumbnails by thumbnailKey (a design at one size, on one object).
    QCache<QString, QImage> mThumbnails{2000};
    /// Thumbnails asked for and not yet back: render key -> thumbnail key, and the keys.
    QHash<std::uint64_t, QString> mRequests;
    QSet<QString> mPending;
    /// The items that show a thumbnail (designs) or a mosaic (generations), by key.
    QMultiHash<QString, QTreeWidgetItem*> mDesignItems;
    QMultiHash<QString, QTreeWidgetItem*> mGenerationItems;
    /// What the user expanded (generations) and collapsed (branches), kept across rebuilds.
    QSet<int> mExpandedGenerations;
    QSet<int> mCollapsedBranches;
    bool mCurrentDesignsFolded = false;
    QTimer mThumbnailTimer;
    /// A click waits out the double-click interval: a double-click means something else.
    QTimer mClickTimer;
    int mClickGeneration = -1;
    int mClickCell = -1;
};

} // namespace marbler::ui

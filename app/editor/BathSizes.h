#pragma once
/// The bath's size and aspect for File ▸ New design: a few named shapes (square, A4 portrait and
/// landscape, 16:9 and 9:16) that set a blank design's Genome::size, as menu entries the editor
/// window appends to its New design menu.

#include "marbler/Genome.h"

#include <QString>

#include <functional>
#include <vector>

class QMenu;

namespace marbler::ui {

/// A named bath shape: its width and height in design units (a solid's depth is the shorter
/// of the two).
struct BathSize {
    QString name;
    double width = 1000, height = 1000;
};

/// The shapes offered, square first (the default design's 1000 × 1000).
std::vector<BathSize> bathSizes();

/// A blank design (blankDesign's palette and name) of that shape, flat (2) or solid (3).
Genome blankDesignOfSize(int dimension, const BathSize& size);

/// Appends to `newMenu` a "Flat bath of size" and a "Solid block of size" submenu, one entry a
/// shape; choosing one calls `open` with the blank design.
void addBathSizeMenus(QMenu* newMenu, const std::function<void(const Genome&)>& open);

} // namespace marbler::ui

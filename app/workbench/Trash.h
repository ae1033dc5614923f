#pragma once
/// A trash folder for files the user removes (favourites, kept sessions): removing moves the file
/// in, so it can be brought back until the trash is emptied. A trashed file's name starts with
/// the time it was trashed ("20261202T140512Z-NAME"), which says how old it is without relying on
/// file times (a move keeps the modification time, and restoring should keep it too).

#include <QString>

namespace marbler::ui {

/// Moves a file into `trashFolder` (created when needed). Returns the trashed file's path, or
/// an empty string when it could not be moved (the file is then left where it was).
QString moveToTrash(const QString& file, const QString& trashFolder);

/// Moves a trashed file back into `folder` under its original name. Returns the restored path,
/// or an empty string when it could not (gone, or a file of that name is there again).
QString restoreFromTrash(const QString& trashed, const QString& folder);

/// The original name of a trashed file (the name without its time prefix).
QString originalTrashName(const QString& trashed);

/// Deletes the files trashed more than `days` days ago; returns how many were deleted.
int emptyTrash(const QString& trashFolder, int days);

} // namespace marbler::ui

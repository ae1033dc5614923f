#pragma once
/// The breeding session on disk: every generation's nine designs, the current generation, the
/// session seed, the population's kind and the objects designs are shown on. The model
/// writes it (atomically) after every change of the population, so a crash or a closed window
/// loses nothing; the next start offers to resume it.
///
/// Version 3 (issue 28): a small head document per session, kept in the session folder's store
/// (SessionStore.h), and one file per generation in a folder beside it, so that a new generation
/// writes one file and the head, whatever the session's length:
///
///     20261202-140512.json                  {"format": "marbler-session", "version": 3, "seed": 42,
///                                            "current": 1, "generation": 2, "dimension": 2, ...,
///                                            "count": 3}
///     20261202-140512.generations/g000000.json   {"description": "...", "parent": -1, ...}
///     20261202-140512.generations/g000001.json   ...
///
/// The head has the members of a version 2 document (below) but `generations`, and `count`, the
/// number of generations: files g000000.json to g(count - 1).json, each one generation object
/// as a version 2 document's `generations` holds them. Each file is written atomically,
/// generation files before the head, so a crash loses at most the generation being made (a file
/// beyond `count` is not read, and is overwritten by the next generation). A generation's file is
/// rewritten only when the generation changes (locks, names, its selection). Versions 1 and 2,
/// one document per session, are still read, and written over as version 3 by the next autosave:
///
///
///     {"format": "marbler-session", "version": 2, "seed": 42, "current": 1, "generation": 2,
///      "dimension": 2, "mesh": "vase", "name": "Flat session, 2 Dec 2026 14:05",
///      "created": "2026-12-02T14:05:12Z",
///      "generations": [{"description": "...", "parent": 0, "parents": [4], "selected": [4],
///                       "cells": [GENOME, null, ...], "bases": ["/dir", null, ...]}, ...]}
///
/// where `parent` is the index of the generation this one grew from (always an earlier one; -1
/// for the first), `parents` the cells whose designs it was bred from, GENOME a genome document
/// exactly as a genome file holds it (marbler::toJson, read back with marbler::parseGenome, so
/// every rule of the genome format is checked on resume), and `bases` the folders relative
/// source images resolve against (absent when none). Version 1 documents, which have no
/// `parent` (each generation grew from the one before), are still read. `name` and `created`
/// (ISO 8601) label the session in the list of kept sessions (SessionStore.h); both are optional,
/// as is `generation`, the current generation's number as the window shows it (for that list).
/// `mesh` is the object solid designs are shown on and `flatMesh` (absent: flat) the one flat
/// designs are shown on, each a built-in name or a mesh file's absolute path; a file that is
/// gone is still read back (the window says so when it cannot show it, and shows a built-in).

#include "marbler/Mesh.h"
#include "workbench/PopulationModel.h"

#include <QString>

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace marbler::ui {

/// A session read back from disk.
struct SavedSession {
    /// At least one generation, numbered (numberGeneration). A generation not `held` (version 3)
    /// is read back from `folder` when wanted.
    std::vector<Generation> history;
    QString folder;  ///< the generations folder of a version 3 session; empty: all are held
    int current = 0; ///< index into history
    std::uint64_t seed = 1;
    int dimension = 2; ///< 2: flat, 3: solid (the kind of the current grid)
    QString mesh = QString::fromLatin1(DefaultMesh);
    QString flatMesh;     ///< empty: flat designs are shown flat
    SessionLabel label{}; ///< empty name, invalid time when the document has none
};

/// The session folder: $MARBLER_SESSION_DIR when set, else the app data folder's "session".
QString defaultSessionFolder();
/// The single session file of a folder before sessions were kept (`session.json`), which
/// SessionStore::migrate() moves into the store.
QString sessionFilePath(const QString& folder);

/// The whole session as one version 2 document (see above): an export; the autosave writes
/// version 3 (serializeSessionHead, serializeGeneration).
std::string serializeSession(const PopulationModel& model);
/// A version 3 session's head (see above).
std::string serializeSessionHead(const PopulationModel& model);
/// One generation's file text (see above).
std::string serializeGeneration(const Generation& generation);
/// The folder of a session file's generations: "NAME.generations" beside "NAME.json".
QString generationsFolder(const QString& sessionFile);
/// The file of generation `index` in such a folder ("g000012.json").
QString generationFile(const QString& folder, int index);
/// Parses one generation's file text (`index`: its place in the history, which its parent must
/// come before). Throws as parseSession.
Generation parseGenerationText(std::string_view text, int index, const std::string& name);
/// Reads one generation's file from a generations folder. Throws as loadSession.
Generation readGeneration(const QString& folder, int index);
/// Parses a session document; `name` names the source in errors. Throws InputError (or
/// GenomeError naming the generation and cell) for anything that breaks the format.
SavedSession parseSession(std::string_view text, const std::string& name);
/// Reads and parses a session file (any version; a version 3 session's generation files are
/// all read and checked, and only the current and the newest few keep their designs in memory:
/// the model reads the others back from `SavedSession::folder`). Throws InputError/GenomeError as
/// parseSession, and RuntimeFailure when the file cannot be read.
SavedSession loadSession(const QString& file);

/// Moves a bad session file aside (`NAME.json.bad`, or `.2.bad`, ... when taken) so that a
/// fresh session can start without destroying it. Returns the new name, empty when it failed.
QString keepBadSession(const QString& file);

} // namespace marbler::ui

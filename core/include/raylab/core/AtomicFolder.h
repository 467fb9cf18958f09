#pragma once

#include "raylab/core/Exception.h"

#include <functional>
#include <string>

namespace raylab {

/**
 * \brief A folder of output written whole (a lesson's handout, an animation's frames): the
 * files go into a new folder beside the target, and commit() swaps it in place of the old
 * one in one step (Linux's renameat2 with RENAME_EXCHANGE), then removes the old.
 *
 * Until commit() the target is untouched: an error, a full disk, Ctrl-C or kill -9 leave
 * the old folder as it was. The new folder is removed when the object dies uncommitted,
 * and by the handlers of SIGINT, SIGTERM and SIGHUP (removeTemporaryFilesOnSignals), which
 * also write "raylab: interrupted: TARGET was not changed"; one left by kill -9 (its name
 * holds the process id) is removed by the next AtomicFolder beside the same target.
 *
 * The old folder is replaced whole, so it may only hold files the command writes
 * (`ours`): a folder holding anything else (a user's own files) is refused rather than
 * lost.
 */
class AtomicFolder {
 public:
  /// Why a folder cannot be written; the message names the folder.
  class Error : public Exception {
   public:
    using Exception::Exception;
  };

  /// Prepares an empty new folder beside `target`. `ours(name)` says whether a file
  /// name in an existing target is one the command writes. Throws Error when the target
  /// is not a folder, holds other files, or no folder can be made beside it.
  AtomicFolder(std::string target, std::function<bool(const std::string&)> ours);
  ~AtomicFolder();
  AtomicFolder(const AtomicFolder&) = delete;
  AtomicFolder& operator=(const AtomicFolder&) = delete;

  /// The new folder: write every file here.
  const std::string& path() const { return m_path; }
  /// The path of `name` in the new folder.
  std::string file(const std::string& name) const;
  /// The target's path as the user gave it (for messages and listings).
  const std::string& target() const { return m_target; }
  /// Puts the new folder in place of the target and removes the old one. Throws Error
  /// (the target unchanged) when the swap fails.
  void commit();

 private:
  std::string m_target;
  std::string m_path;
  std::string m_note;  ///< The interrupt note while this folder is being written.
  bool m_committed = false;
};

}  // namespace raylab

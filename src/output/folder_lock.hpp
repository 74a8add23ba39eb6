// A lock on an output folder, so that two different runs never write into one folder at once, while the
// chunks of one farm render (the same scene and output settings, each with its own --frames) share it.
#pragma once

#include <filesystem>
#include <string>

namespace output {

// The lock file in the folder while a run holds it (the last run out removes it; one a killed run left is
// taken over by the next).
inline constexpr const char* kFolderLockName = ".softbody-lock";

class FolderLock {
 public:
  enum class Sharing {
    Exclusive,    // a whole run: no other run may write into the folder meanwhile
    SameRunOnly,  // a chunk (--frames): shared with other chunks of the same run (equal `run_identity`)
  };
  // Locks `dir` for this process until destruction; a folder it had to create is removed again then if it is
  // still empty (a run that failed before writing leaves nothing). `run_identity` says which run this is
  // (the command, the scene's hash, the output settings): chunks share the folder only when theirs are equal.
  // `holder` says who holds it in another run's message ("render scenes/bounce.json"). Throws
  // softbody::InputError naming the folder when another run holds it; where the file system refuses locks (or
  // the lock file cannot be written), prints a note and goes on unlocked.
  FolderLock(const std::filesystem::path& dir, const std::string& run_identity, Sharing sharing,
             const std::string& holder);
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

 private:
  // Opens the lock file and takes its guard byte, opening again when the file was removed meanwhile.
  void open_holding_the_guard();
  // Takes the folder's byte exclusively; false when another run holds it.
  bool take_folder_byte() const;

  std::filesystem::path path_;
  int fd_ = -1;
  bool created_folder_ = false;
};

}  // namespace output

// shitsukan/core/output_file.hpp — every file the library writes: complete or not there at all.
//
// Manual
//   OutputFile out;
//   Status s = out.open("notes.txt");        // a temporary beside it: ".notes.txt.<pid>-<n>.tmp"
//   if (s) {
//       out.print("%d scales\n", 42);        // every write, flush and close is checked
//       out.write("done\n", 5);
//       s = out.commit();                    // renamed onto notes.txt only when complete
//   }                                        // (an uncommitted file's temporary is removed)
//   OutputSet set;                           // several files: all of them or none
//   if (s) s = write_text_file("a.txt", "first\n");
//   if (s) s = write_text_file("b.txt", "second\n");
//   if (s) s = set.commit();                 // a.txt and b.txt appear together, or neither
//   if (!s) std::fprintf(stderr, "%s\n", s.message());  // "cannot write d/x.png: <reason>"
//   remove_temporaries_on_signals();         // a tool's main(): Ctrl-C leaves no temporary
//
// open() makes a temporary in the target's directory (mode 0666 less the umask, or the old
// file's mode when it replaces one); commit() closes it (fflush and fclose checked) and renames
// it onto the target, so a reader sees the old file or the new one, never a part, and a failed
// write (disk full, `ulimit -f`, a write error) leaves the old file intact and no temporary.
// Targets that are not regular files (/dev/null, /dev/stdout, a FIFO) are written in place.
// Errors are io_error, naming the path and the reason from the C library (strerror):
//   missing directory      cannot write d/x.png: directory d: No such file or directory
//   read-only directory    cannot write d/x.png: directory d: Permission denied
//   read-only file         cannot write d/x.png: Permission denied (the file is read-only)
//   a directory in the way cannot write d/x.png: Is a directory
//   disk full              cannot write d/x.png: No space left on device (File too large
//                          past `ulimit -f` once remove_temporaries_on_signals() ignores
//                          SIGXFSZ)
//
// OutputSet: while one lives on a thread, every OutputFile committed on that thread (so every
// writer of the library: write_png, write_png16, write_pfm, write_obj, SvgCanvas::save,
// write_bark_csv, ...) is completed but kept under its temporary name; set.commit() renames them
// all (a file it replaces is kept as a hard link until every rename has succeeded, and put back
// if one fails); a set destroyed without commit() removes them. Sets nest (the inner one hands
// its files to the outer one on commit). SIGINT, SIGTERM and SIGHUP are held during the renames.
//
// remove_temporaries_on_signals(): handlers for SIGINT, SIGTERM and SIGHUP (unless ignored)
// that unlink every temporary still open or held by a set (async-signal-safe: unlink only),
// then restore the default action and re-raise the signal, so the exit status says which one;
// SIGXFSZ is ignored so that a write past the file-size limit fails with a reason instead of
// killing the process. Call once from main(), before starting threads.
//
// Chosen here: no fsync before the rename (the issue is lost or half-written output, which the
// checked writes and the rename prevent; fsync would slow every figure run for power-loss
// safety, which no reader of these files needs). Host side: POSIX (open, rename, link, unlink).
#pragma once

#include <cstddef>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "shitsukan/core/status.hpp"

namespace shitsukan {

class OutputFile {
public:
    OutputFile() = default;
    ~OutputFile();  // without commit(): closes and removes the temporary
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;

    Status open(const char* path);
    Status open(const std::string& path) { return open(path.c_str()); }
    // Failures are remembered (the first one's errno) and reported by commit().
    void write(const void* data, std::size_t size);
    void print(const char* format, ...)
#if defined(__GNUC__)
        __attribute__((format(printf, 2, 3)))
#endif
        ;
    bool failed() const { return error_ != 0; }
    // Closes the file (every failure so far, fflush and fclose checked), then renames it onto
    // the path (or hands it to the thread's OutputSet).
    Status commit();
    const std::string& path() const { return path_; }

private:
    void discard();
    Status fail(const char* what, int error);
    std::FILE* f_ = nullptr;
    std::string path_;    // as given (messages)
    std::string target_;  // what is replaced: path_, or where its symbolic link points
    std::string temp_;    // empty: written in place (not a regular file)
    int slot_ = -1;            // in the signal handler's list of temporaries
    int error_ = 0;            // the first failure's errno
};

class OutputSet {
public:
    OutputSet();   // becomes the thread's set
    ~OutputSet();  // without commit(): removes every temporary it holds
    OutputSet(const OutputSet&) = delete;
    OutputSet& operator=(const OutputSet&) = delete;
    Status commit();

private:
    friend class OutputFile;
    struct Held {
        std::string path, temp, backup;  // backup: a hard link to the file it replaces
        int slot = -1;
    };
    void hold(std::unique_ptr<Held> held);
    Status rename_all();
    std::vector<std::unique_ptr<Held>> held_;  // never moved: the signal handler reads names
    OutputSet* outer_ = nullptr;
    bool active_ = true;
};

// The whole text as one file (open, write, commit).
Status write_text_file(const char* path, const std::string& text);

void remove_temporaries_on_signals();

}  // namespace shitsukan

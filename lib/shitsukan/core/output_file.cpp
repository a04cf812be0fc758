// Host side: files written under a temporary name and renamed into place (output_file.hpp).
#include "shitsukan/core/output_file.hpp"

#include <atomic>
#include <cerrno>
#include <cstdarg>
#include <cstdlib>
#include <cstring>

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

namespace shitsukan {

namespace {

// The temporaries a signal handler must remove: pointers to names that stay valid while
// registered (lock-free atomics, so the handler may read them).
constexpr int kTemporarySlots = 256;
std::atomic<const char*> g_temporaries[kTemporarySlots];
std::atomic<unsigned> g_counter{0};
thread_local OutputSet* t_set = nullptr;

// -1 when all slots are taken: the temporary is still removed on every failure, only not by
// a signal handler.
int register_temporary(const char* name) {
    for (int i = 0; i < kTemporarySlots; ++i) {
        const char* expected = nullptr;
        if (g_temporaries[i].compare_exchange_strong(expected, name)) return i;
    }
    return -1;
}

void unregister_temporary(int& slot) {
    if (slot >= 0) g_temporaries[slot].store(nullptr);
    slot = -1;
}

void remove_temporaries_and_reraise(int sig) {
    for (std::atomic<const char*>& t : g_temporaries)
        if (const char* name = t.load()) unlink(name);
    signal(sig, SIG_DFL);
    raise(sig);  // delivered when the handler returns: the default action, the right status
}

std::string directory_of(const std::string& path) {
    const std::size_t slash = path.rfind('/');
    if (slash == std::string::npos) return ".";
    return slash == 0 ? "/" : path.substr(0, slash);
}

// "<dir>/.<name>.<pid>-<n>.<kind>" beside `path` (the name cut to stay under NAME_MAX).
std::string sibling_name(const std::string& path, const char* kind) {
    const std::size_t slash = path.rfind('/');
    const std::string dir = slash == std::string::npos ? "" : path.substr(0, slash + 1);
    const std::string name = path.substr(slash == std::string::npos ? 0 : slash + 1, 200);
    char tail[64];
    std::snprintf(tail, sizeof tail, ".%ld-%u.%s", long(getpid()), g_counter.fetch_add(1), kind);
    return dir + "." + name + tail;
}

const char* reason(int error) { return std::strerror(error != 0 ? error : EIO); }

// SIGINT, SIGTERM and SIGHUP held while a set renames its files.
struct HeldSignals {
    sigset_t old;
    HeldSignals() {
        sigset_t set;
        sigemptyset(&set);
        sigaddset(&set, SIGINT);
        sigaddset(&set, SIGTERM);
        sigaddset(&set, SIGHUP);
        pthread_sigmask(SIG_BLOCK, &set, &old);
    }
    ~HeldSignals() { pthread_sigmask(SIG_SETMASK, &old, nullptr); }
};

}  // namespace

OutputFile::~OutputFile() { discard(); }

void OutputFile::discard() {
    if (f_) std::fclose(f_);  // the file is dropped: its close status does not matter
    f_ = nullptr;
    if (!temp_.empty()) unlink(temp_.c_str());
    unregister_temporary(slot_);
    temp_.clear();
}

Status OutputFile::fail(const char* what, int error) {
    discard();
    if (what != nullptr)
        return Status::error(StatusCode::io_error, "cannot write %s: %s %s: %s", path_.c_str(),
                             what, directory_of(target_).c_str(), reason(error));
    return Status::error(StatusCode::io_error, "cannot write %s: %s", path_.c_str(),
                         reason(error));
}

Status OutputFile::open(const char* path) {
    discard();
    error_ = 0;
    if (path == nullptr || path[0] == '\0')
        return Status::error(StatusCode::invalid_argument, "output path is empty");
    path_ = target_ = path;
    struct stat st;
    mode_t mode = 0666;
    bool replacing = false;
    if (stat(path, &st) == 0) {
        if (S_ISDIR(st.st_mode)) return fail(nullptr, EISDIR);
        if (!S_ISREG(st.st_mode)) {  // a device or a FIFO: written in place
            f_ = std::fopen(path, "wb");
            return f_ ? Status::success() : fail(nullptr, errno);
        }
        if (faccessat(AT_FDCWD, path, W_OK, AT_EACCESS) != 0)
            return Status::error(StatusCode::io_error, "cannot write %s: %s (the file is read-only)",
                                 path, reason(errno));
        if (char* real = realpath(path, nullptr)) {  // a symbolic link stays one
            target_ = real;
            std::free(real);
        }
        mode = st.st_mode & 07777;
        replacing = true;
    }
    int fd = -1;
    for (int attempt = 0; fd < 0 && attempt < 100; ++attempt) {
        temp_ = sibling_name(target_, "tmp");
        slot_ = register_temporary(temp_.c_str());  // before it exists: no unlisted moment
        fd = ::open(temp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd < 0) unregister_temporary(slot_);
        if (fd < 0 && errno != EEXIST) {
            const int e = errno;
            temp_.clear();
            return fail("directory", e);
        }
    }
    if (fd < 0) {
        temp_.clear();
        return fail("directory", EEXIST);
    }
    if (replacing) (void)fchmod(fd, mode);  // keep the old file's mode; a failure keeps 0666
    f_ = fdopen(fd, "wb");
    if (f_ == nullptr) {
        const int e = errno;
        close(fd);
        return fail(nullptr, e);
    }
    return Status::success();
}

void OutputFile::write(const void* data, std::size_t size) {
    if (f_ == nullptr || error_ != 0 || size == 0) return;
    errno = 0;
    if (std::fwrite(data, 1, size, f_) != size) error_ = errno != 0 ? errno : EIO;
}

void OutputFile::print(const char* format, ...) {
    if (f_ == nullptr || error_ != 0) return;
    va_list args;
    va_start(args, format);
    errno = 0;
    if (std::vfprintf(f_, format, args) < 0) error_ = errno != 0 ? errno : EIO;
    va_end(args);
}

Status OutputFile::commit() {
    if (f_ == nullptr)
        return Status::error(StatusCode::io_error, "cannot write %s: the file is not open",
                             path_.empty() ? "(no path)" : path_.c_str());
    errno = 0;
    if (error_ == 0 && (std::fflush(f_) != 0 || std::ferror(f_)))
        error_ = errno != 0 ? errno : EIO;
    errno = 0;
    const bool closed = std::fclose(f_) == 0;
    f_ = nullptr;
    if (!closed && error_ == 0) error_ = errno != 0 ? errno : EIO;
    if (error_ != 0) return fail(nullptr, error_);
    if (temp_.empty()) return Status::success();
    if (t_set != nullptr) {
        t_set->hold(std::unique_ptr<OutputSet::Held>(
            new OutputSet::Held{target_, temp_, std::string(), -1}));
    } else if (std::rename(temp_.c_str(), target_.c_str()) != 0) {
        return fail(nullptr, errno);
    }
    unregister_temporary(slot_);
    temp_.clear();
    return Status::success();
}

OutputSet::OutputSet() : outer_(t_set) { t_set = this; }

OutputSet::~OutputSet() {
    if (active_) t_set = outer_;
    for (const std::unique_ptr<Held>& h : held_) {
        unlink(h->temp.c_str());
        unregister_temporary(h->slot);
    }
}

void OutputSet::hold(std::unique_ptr<Held> held) {
    if (held->slot < 0) held->slot = register_temporary(held->temp.c_str());
    held_.push_back(std::move(held));
}

Status OutputSet::commit() {
    if (!active_) return Status::error(StatusCode::io_error, "output set committed twice");
    active_ = false;
    t_set = outer_;
    if (outer_ != nullptr) {  // the enclosing set renames them
        for (std::unique_ptr<Held>& h : held_) outer_->hold(std::move(h));
        held_.clear();
        return Status::success();
    }
    const HeldSignals held_signals;
    Status s = rename_all();
    for (const std::unique_ptr<Held>& h : held_) unregister_temporary(h->slot);
    held_.clear();
    return s;
}

// Every file it replaces kept as a hard link first; then the renames; on a failure the
// renamed ones are put back (or removed when they are new) and the rest removed.
Status OutputSet::rename_all() {
    struct stat st;
    for (const std::unique_ptr<Held>& h : held_)
        if (lstat(h->path.c_str(), &st) == 0 && S_ISREG(st.st_mode)) {
            h->backup = sibling_name(h->path, "old");
            if (link(h->path.c_str(), h->backup.c_str()) != 0) h->backup.clear();
        }
    std::size_t done = 0;
    int error = 0;
    for (; done < held_.size(); ++done)
        if (std::rename(held_[done]->temp.c_str(), held_[done]->path.c_str()) != 0) {
            error = errno;
            break;
        }
    for (std::size_t i = 0; i < held_.size(); ++i) {
        const Held* h = held_[i].get();
        if (error != 0 && i < done) {
            if (h->backup.empty() || std::rename(h->backup.c_str(), h->path.c_str()) != 0)
                unlink(h->path.c_str());
        } else if (error != 0) {
            unlink(h->temp.c_str());
        }
        if (!h->backup.empty()) unlink(h->backup.c_str());
    }
    if (error == 0) return Status::success();
    return Status::error(StatusCode::io_error, "cannot write %s: %s (none of the %zu files written)",
                         held_[done]->path.c_str(), reason(error), held_.size());
}

Status write_text_file(const char* path, const std::string& text) {
    OutputFile out;
    SHITSUKAN_TRY(out.open(path));
    out.write(text.data(), text.size());
    return out.commit();
}

void remove_temporaries_on_signals() {
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
        struct sigaction old;
        if (sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;  // nohup
        struct sigaction sa;
        std::memset(&sa, 0, sizeof sa);
        sa.sa_handler = remove_temporaries_and_reraise;
        sigemptyset(&sa.sa_mask);
        sigaction(sig, &sa, nullptr);
    }
    signal(SIGXFSZ, SIG_IGN);
}

}  // namespace shitsukan

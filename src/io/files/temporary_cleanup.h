#pragma once
// Temporary files that must not outlive an interrupted save. While a save runs, its temporary file is
// registered here; SIGINT, SIGTERM or SIGHUP then remove every registered file before the process
// dies of the signal as it would have without us (so the shell still sees 128 + N).
//
// The handler only reads lock-free atomics and calls unlink and raise, which are async-signal-safe.
// Handlers are installed on first use, and only for signals still at their default disposition, so
// a program that handles these signals itself keeps its handlers (and its responsibility). SIGXFSZ,
// if at its default, is ignored from then on: exceeding a file-size limit becomes a write error
// (EFBIG) that the save reports and cleans up, instead of killing the process mid-write.
#include <signal.h>

namespace rgbio {

class TemporaryRegistration {
public:
    // `path` must stay valid and unchanged until the registration ends. If all slots are taken
    // (more concurrent saves than kSlots), the file is simply not cleaned up on a signal.
    explicit TemporaryRegistration(const char* path);
    ~TemporaryRegistration() { release(); }
    TemporaryRegistration(const TemporaryRegistration&) = delete;
    TemporaryRegistration& operator=(const TemporaryRegistration&) = delete;

    // The file is gone or renamed into place: a signal must no longer remove it.
    void release();

    static constexpr int kSlots = 16;

private:
    int slot_ = -1;
};

// Holds SIGINT, SIGTERM and SIGHUP back (they stay pending) while an instance lives, for the part of
// a save that must not be cut short: writing an existing file in place.
class DeferredTerminationSignals {
public:
    DeferredTerminationSignals();
    ~DeferredTerminationSignals();
    DeferredTerminationSignals(const DeferredTerminationSignals&) = delete;
    DeferredTerminationSignals& operator=(const DeferredTerminationSignals&) = delete;

private:
    sigset_t previous_;
};

}  // namespace rgbio

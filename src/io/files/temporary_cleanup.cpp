#include "io/files/temporary_cleanup.h"

#include <atomic>
#include <mutex>

#include <unistd.h>

namespace rgbio {
namespace {

static_assert(std::atomic<const char*>::is_always_lock_free, "the signal handler may only touch lock-free atomics");

std::atomic<const char*> registered[TemporaryRegistration::kSlots];

constexpr int kTerminationSignals[] = {SIGINT, SIGTERM, SIGHUP};

extern "C" void remove_temporaries_and_die(int signal) {
    for (std::atomic<const char*>& slot : registered)
        if (const char* path = slot.exchange(nullptr)) ::unlink(path);
    // SA_RESETHAND restored the default action; the raised signal is delivered when this returns.
    ::raise(signal);
}

void install_handlers() {
    for (int signal : kTerminationSignals) {
        struct sigaction current {};
        if (::sigaction(signal, nullptr, &current) != 0 || current.sa_handler != SIG_DFL) continue;
        struct sigaction cleanup {};
        cleanup.sa_handler = remove_temporaries_and_die;
        cleanup.sa_flags = SA_RESETHAND;
        sigemptyset(&cleanup.sa_mask);
        for (int other : kTerminationSignals) sigaddset(&cleanup.sa_mask, other);
        ::sigaction(signal, &cleanup, nullptr);
    }
    struct sigaction size_limit {};
    if (::sigaction(SIGXFSZ, nullptr, &size_limit) == 0 && size_limit.sa_handler == SIG_DFL) ::signal(SIGXFSZ, SIG_IGN);
}

}  // namespace

TemporaryRegistration::TemporaryRegistration(const char* path) {
    static std::once_flag installed;
    std::call_once(installed, install_handlers);
    for (int i = 0; i < kSlots; ++i) {
        const char* empty = nullptr;
        if (registered[i].compare_exchange_strong(empty, path)) {
            slot_ = i;
            return;
        }
    }
}

void TemporaryRegistration::release() {
    if (slot_ >= 0) registered[slot_].store(nullptr);
    slot_ = -1;
}

DeferredTerminationSignals::DeferredTerminationSignals() {
    sigset_t held;
    sigemptyset(&held);
    for (int signal : kTerminationSignals) sigaddset(&held, signal);
    ::pthread_sigmask(SIG_BLOCK, &held, &previous_);
}

DeferredTerminationSignals::~DeferredTerminationSignals() { ::pthread_sigmask(SIG_SETMASK, &previous_, nullptr); }

}  // namespace rgbio

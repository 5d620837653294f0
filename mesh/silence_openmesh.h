// Mutes OpenMesh's own console output for a scope: its readers and the
// decimater print to omerr()/omlog(), while unfold reports problems through
// exceptions and glog instead.
#pragma once

#include <OpenMesh/Core/System/omstream.hh>

namespace unfold {

/// RAII guard: disables omerr(), omlog() and omout() and restores their
/// previous state on destruction. Not thread-safe (the streams are global).
class SilenceOpenMesh {
 public:
  SilenceOpenMesh()
      : err_(::omerr().is_enabled()), log_(::omlog().is_enabled()), out_(::omout().is_enabled()) {
    ::omerr().disable();
    ::omlog().disable();
    ::omout().disable();
  }
  ~SilenceOpenMesh() {
    if (err_) ::omerr().enable();
    if (log_) ::omlog().enable();
    if (out_) ::omout().enable();
  }
  SilenceOpenMesh(const SilenceOpenMesh&) = delete;
  SilenceOpenMesh& operator=(const SilenceOpenMesh&) = delete;

 private:
  bool err_, log_, out_;
};

}  // namespace unfold

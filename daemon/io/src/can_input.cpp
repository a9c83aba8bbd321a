#include "cyber/daemon/io/can_input.hpp"

#include "cyber/can/frame_kind.hpp"
#include "cyber/daemon/io/monotonic_clock.hpp"

namespace cyber::daemon::io {

namespace {

constexpr int kMaxFramesPerWake = 64;
constexpr MonoNs kPauseAfterReadError = 100'000'000;

}  // namespace

CanInput::CanInput(can::CanSocket& socket, EventLoop& loop) : socket_(socket), loop_(loop) { watch(); }

void CanInput::watch() {
  loop_.add(socket_.fd(), [this] { onReadable(); });
}

void CanInput::onTimer(MonoNs now) {
  if (paused_until_ == kNever || now < paused_until_) return;
  paused_until_ = kNever;
  watch();
}

void CanInput::onReadable() {
  const MonoNs now = monotonicNow();
  can::Frame frame;
  for (int i = 0; i < kMaxFramesPerWake; ++i) {
    const can::IoResult result = socket_.read(frame);
    if (result.status == can::IoStatus::kWouldBlock) return;
    if (!result.ok()) {
      ++read_errors_;
      warning_.warn(now, "CAN read failed: {}; retrying in 100 ms", result.message());
      loop_.remove(socket_.fd());
      paused_until_ = now + kPauseAfterReadError;
      return;
    }
    if (can::classify(frame) != can::FrameKind::kBusError) continue;  // the socket passes no data frames
    ++bus_errors_;
    bus_error_ns_ = now;
    warning_.warn(now, "CAN controller error frame (id 0x{:08x})", frame.id);
  }
}

}  // namespace cyber::daemon::io

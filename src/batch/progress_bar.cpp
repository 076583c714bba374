#include "batch/progress_bar.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

namespace linkproof {

namespace {

std::string clock_time(double seconds) {
  const long s = static_cast<long>(seconds + 0.5);
  return fmt::format("{}:{:02}:{:02}", s / 3600, s / 60 % 60, s % 60);
}

}  // namespace

ProgressBar::ProgressBar(std::ostream* out, long total, long done_before)
    : out_(out), total_(total), done_before_(done_before), start_(std::chrono::steady_clock::now()) {}

std::string ProgressBar::render(long done, long total, double rate, long failures) {
  constexpr int kWidth = 20;
  const double fraction = total > 0 ? static_cast<double>(done) / static_cast<double>(total) : 1.0;
  const int filled = static_cast<int>(fraction * kWidth);
  const std::string eta = rate > 0 ? clock_time(static_cast<double>(total - done) / rate) : "?";
  return fmt::format("{:>7}/{} cases {:>3.0f}% |{}{}| {:>7.1f} cases/s  ETA {}  failures {}", done, total,
                     100 * fraction, std::string(static_cast<size_t>(filled), '#'),
                     std::string(static_cast<size_t>(kWidth - filled), ' '), rate, eta, failures);
}

void ProgressBar::draw(long done, long failures) {
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double rate = elapsed > 0 ? static_cast<double>(done - done_before_) / elapsed : 0;
  fmt::print(*out_, "\r{}", render(done, total_, rate, failures));
  out_->flush();
  drawn_ = true;
}

void ProgressBar::update(long done, long failures) {
  if (out_ == nullptr) return;
  const auto now = std::chrono::steady_clock::now();
  if (drawn_ && now - last_draw_ < std::chrono::milliseconds(200)) return;
  last_draw_ = now;
  draw(done, failures);
}

void ProgressBar::finish(long done, long failures) {
  if (out_ == nullptr) return;
  draw(done, failures);
  *out_ << "\n";
}

}  // namespace linkproof

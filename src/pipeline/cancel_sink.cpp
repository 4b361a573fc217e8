#include "strata/pipeline/cancel_sink.hpp"

namespace strata {

Result<void> CancelSink::check() const {
  if (cancel_.load(std::memory_order_relaxed)) {
    return Error{ErrorCode::Internal, kCancelledMessage, {}};
  }
  return {};
}

Result<void> CancelSink::begin(const SliceRunInfo& /*run*/) { return check(); }

Result<void> CancelSink::add_layer(const LayerResult& /*layer*/) { return check(); }

Result<void> CancelSink::finish() { return check(); }

bool is_cancelled(const Error& error) {
  return error.code == ErrorCode::Internal && error.message == kCancelledMessage &&
         error.location.empty();
}

}  // namespace strata

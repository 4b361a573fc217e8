#pragma once

#include <optional>
#include <utility>
#include <variant>

#include "strata/core/error.hpp"

namespace strata {

/// A value or an Error; the project's substitute for std::expected until C++23.
template <class T>
class [[nodiscard]] Result {
 public:
  /// A success; implicit, so that a function returns its value as it is.
  Result(T value)
      : state_(std::in_place_index<0>, std::move(value)) {}  // NOLINT: implicit by design
  /// A failure; implicit, so that a function returns an Error as it is.
  Result(Error error) : state_(std::in_place_index<1>, std::move(error)) {}  // NOLINT

  /// True when it holds a value, false when it holds an Error.
  bool has_value() const { return state_.index() == 0; }
  /// has_value().
  explicit operator bool() const { return has_value(); }

  /// The value. @pre has_value() (std::bad_variant_access is thrown otherwise).
  /// @{
  T& value() & { return std::get<0>(state_); }
  const T& value() const& { return std::get<0>(state_); }
  T&& value() && { return std::get<0>(std::move(state_)); }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }
  T& operator*() & { return value(); }
  const T& operator*() const& { return value(); }
  /// @}

  /// The error. @pre !has_value() (std::bad_variant_access is thrown otherwise).
  const Error& error() const { return std::get<1>(state_); }

 private:
  std::variant<T, Error> state_;
};

/// Success, or an Error.
template <>
class [[nodiscard]] Result<void> {
 public:
  /// Success.
  Result() = default;
  /// A failure; implicit, so that a function returns an Error as it is.
  Result(Error error) : error_(std::move(error)) {}  // NOLINT: implicit by design

  /// True on success.
  bool has_value() const { return !error_.has_value(); }
  /// has_value().
  explicit operator bool() const { return has_value(); }
  /// The error. @pre !has_value().
  const Error& error() const { return *error_; }

 private:
  std::optional<Error> error_;
};

}  // namespace strata

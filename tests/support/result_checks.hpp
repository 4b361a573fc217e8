#pragma once

#include <gtest/gtest.h>

#include <string_view>
#include <utility>

#include "strata/core/error.hpp"
#include "strata/core/result.hpp"

namespace strata::test {

/// The value a call returned; fails the current test, showing `input` (what was read or done)
/// and the error, when it returned an error (and then gives an empty value).
template <class T>
T value_of(Result<T> result, std::string_view input) {
  EXPECT_TRUE(result.has_value()) << input << ": " << result.error().to_string();
  return result ? std::move(result).value() : T{};
}

/// The error a reader returned; fails the current test, showing `input`, when it read
/// (and then gives an empty error).
template <class T>
Error error_of(const Result<T>& result, std::string_view input) {
  EXPECT_FALSE(result.has_value()) << input << " was read without error";
  return result ? Error{} : result.error();
}

/// Fails the current test unless the reader refused the input as bad, at `location`, with
/// exactly `message`.
template <class T>
void expect_bad_input(const Result<T>& result, std::string_view location, std::string_view message,
                      std::string_view input) {
  ASSERT_FALSE(result.has_value()) << input << " was read without error";
  EXPECT_EQ(result.error().code, ErrorCode::BadInput);
  EXPECT_EQ(result.error().location, location);
  EXPECT_EQ(result.error().message, message);
}

}  // namespace strata::test

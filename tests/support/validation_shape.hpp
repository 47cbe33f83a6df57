#pragma once
//! The validation shape of every parameter struct (include/smoothsteer/validation.hpp): the three
//! calls exist, is_valid() is noexcept, and all three agree on the one message.

#include <gtest/gtest.h>

#include <concepts>
#include <stdexcept>
#include <string>

namespace smoothsteer::testing {

template <typename T>
concept HasValidationShape = requires(const T& value) {
  { value.is_valid() }
  noexcept->std::same_as<bool>;
  { value.validation_error() } -> std::same_as<std::string>;
  value.validate();
};

template <HasValidationShape T>
void expect_shape(const T& valid, const T& invalid, const std::string& expected_message) {
  EXPECT_TRUE(valid.is_valid()) << valid.validation_error();
  EXPECT_EQ(valid.validation_error(), "");
  EXPECT_NO_THROW(valid.validate());
  EXPECT_FALSE(invalid.is_valid());
  EXPECT_EQ(invalid.validation_error(), expected_message);
  try {
    invalid.validate();
    ADD_FAILURE() << "validate() accepted " << expected_message;
  } catch (const std::invalid_argument& error) {
    EXPECT_EQ(std::string(error.what()), expected_message);
  }
}

}  // namespace smoothsteer::testing

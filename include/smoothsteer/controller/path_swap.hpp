#pragma once
//! \file path_swap.hpp
//! The common part of every controller's set_path(): swap the shared path pointer and re-seed
//! the projection hints on the new path (SteeringController::set_path states the contract).

#include <memory>
#include <utility>

#include "smoothsteer/path/path.hpp"
#include "smoothsteer/status.hpp"

namespace smoothsteer {

//! Replaces `current` by `next` and moves every hint to the new path near where it pointed on
//! the old one. noexcept, no allocation; the old path is released when `next` (now holding it)
//! goes out of scope in the caller's set_path().
template <typename... Hints>
Status swap_path(std::shared_ptr<const Path>& current, std::shared_ptr<const Path>& next,
                 Hints&... hints) noexcept {
  if (!next) return Status::invalid_input;
  if (current) ((hints = next->reseed_hint(*current, hints)), ...);
  current.swap(next);
  return Status::ok;
}

}  // namespace smoothsteer

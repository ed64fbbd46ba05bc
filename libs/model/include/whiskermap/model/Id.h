#pragma once
#include <cstdint>

namespace whiskermap::model
{
/** Stable id of a hypothesis on the blackboard: an index into its type's slot vector. */
using Id = int32_t;
/** "No hypothesis": a missing parent link, a missing corner. */
constexpr Id NONE = -1;
}  // namespace whiskermap::model

#pragma once
// Sizes a model may reach, checked before anything that large is allocated.

namespace tunica {

constexpr long kMaxNodes = 10'000'000;  ///< nodes in all parts of a model together

}  // namespace tunica

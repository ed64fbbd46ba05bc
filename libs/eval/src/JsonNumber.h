#pragma once
// The evaluation reports' numbers (internal to libs/eval): fixed decimals, NaN as `undefined`.
#include <cmath>
#include <cstdio>
#include <string>

namespace whiskermap::eval::detail
{
/** `v` with `decimals` decimals, or `undefined` when NaN. */
inline std::string num(double v, int decimals = 6, const char* undefined = "null")
{
	if (std::isnan(v)) return undefined;
	char buf[64];
	std::snprintf(buf, sizeof(buf), "%.*f", decimals, v);
	return buf;
}
}  // namespace whiskermap::eval::detail

#include <whiskermap/core/Error.h>
#include <whiskermap/eval/EvalOptions.h>

#include <cmath>
#include <string>

namespace whiskermap::eval
{
void EvalOptions::validate() const
{
	auto require = [](bool ok, const char* what) {
		if (!ok) throw core::Error(std::string("evaluation options: ") + what);
	};
	require(std::isfinite(gate_distance) && gate_distance > 0, "gate_distance must be > 0");
	require(gate_yaw_deg > 0 && gate_yaw_deg <= 90, "gate_yaw_deg must be in (0, 90]");
	require(std::isfinite(wall_gate) && wall_gate > 0, "wall_gate must be > 0");
	require(std::isfinite(ospa_c) && ospa_c > 0, "ospa_c must be > 0");
	require(std::isfinite(ospa_p) && ospa_p >= 1, "ospa_p must be >= 1");
	require(std::isfinite(local_radius) && local_radius > 0, "local_radius must be > 0");
	require(std::isfinite(rpe_segment_m) && rpe_segment_m > 0, "rpe_segment_m must be > 0");
}
}  // namespace whiskermap::eval

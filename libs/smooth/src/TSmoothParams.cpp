#include <whiskermap/core/Angles.h>
#include <whiskermap/core/IniSection.h>
#include <whiskermap/smooth/TSmoothParams.h>

namespace whiskermap::smooth
{
TSmoothParams TSmoothParams::load(const std::string& path)
{
	const auto file = core::openIniFile(path, "slam config file");
	core::IniSection sec(*file, "smooth", path);
	TSmoothParams p;
	p.enabled = sec.boolean("enabled", p.enabled);
	p.gate = sec.number("gate", p.gate, 1e-4, 10);
	p.normal_gate = core::deg2rad(sec.number("normal_gate_deg", core::rad2deg(p.normal_gate), 1, 180));
	p.position_floor = sec.number("position_floor", p.position_floor, 1e-5, 1);
	p.huber = sec.number("huber", p.huber, 0.1, 100);
	p.wall_merge = sec.number("wall_merge", p.wall_merge, 0, 100);
	p.duplicate_sigma = sec.number("duplicate_sigma", p.duplicate_sigma, 0, 10);
	p.duplicate_shrink = sec.number("duplicate_shrink", p.duplicate_shrink, 0, 10);
	p.duplicate_distance = sec.number("duplicate_distance", p.duplicate_distance, 0, 10);
	p.duplicate_wall_distance = sec.number("duplicate_wall_distance", p.duplicate_wall_distance, 0, 10);
	p.solid_sigma = sec.number("solid_sigma", p.solid_sigma, 1e-3, 1000);
	p.table_sigma = sec.number("table_sigma", p.table_sigma, 0, 10);
	p.bridge_gate = sec.number("bridge_gate", p.bridge_gate, 0, 1000);
	p.bridge_window = static_cast<unsigned>(sec.integer("bridge_window", p.bridge_window, 1, 1000));
	p.bridge_short_window = static_cast<unsigned>(sec.integer("bridge_short_window", p.bridge_short_window, 0, 1000));
	p.stretch_margin = static_cast<unsigned>(sec.integer("stretch_margin", p.stretch_margin, 0, 1000));
	p.rounds = static_cast<unsigned>(sec.integer("rounds", p.rounds, 1, 100));
	p.iterations = static_cast<unsigned>(sec.integer("iterations", p.iterations, 1, 1000));
	p.passes = static_cast<unsigned>(sec.integer("passes", p.passes, 1, 100));
	sec.finish();
	return p;
}
}  // namespace whiskermap::smooth

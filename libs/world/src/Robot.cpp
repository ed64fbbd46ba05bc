#include <whiskermap/core/Angles.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/core/IniSection.h>
#include <whiskermap/world/Robot.h>

namespace whiskermap::world
{
Robot Robot::load(const std::string& path)
{
	using core::deg2rad;
	const auto file = core::openIniFile(path, "robot file");
	const auto& cfg = *file;
	core::rejectUnknownSections(cfg, {"robot"}, "whisker_", path);
	core::IniSection sec(cfg, "robot", path);
	Robot r;
	r.radius = sec.number("radius", 0.01, 10);
	const double sx = sec.number("sensor_x", 0.0, -10, 10);
	const double sy = sec.number("sensor_y", 0.0, -10, 10);
	const double syaw = deg2rad(sec.number("sensor_yaw_deg", 0.0, -360, 360));
	r.sensorPose = mrpt::poses::CPose3D(sx, sy, 0, syaw, 0, 0);
	const long n = sec.integer("whisker_count", 1, 1024);
	sec.finish();
	for (long i = 0; i < n; i++)
	{
		core::IniSection w(cfg, "whisker_" + std::to_string(i), path);
		if (!cfg.sectionExists(w.section())) w.fail("", "missing section (whisker_count=" + std::to_string(n) + ")");
		obs::TWhisker m;
		m.mount_x = w.number("mount_x", -10, 10);
		m.mount_y = w.number("mount_y", -10, 10);
		m.sweep_start = deg2rad(w.number("sweep_start_deg", -360, 360));
		m.sweep_end = deg2rad(w.number("sweep_end_deg", -360, 360));
		m.length = w.number("length", 1e-3, 10);
		w.finish();
		if (std::abs(m.sweep_end - m.sweep_start) >= 2 * M_PI)
			w.fail("sweep_end_deg", "a whisk must sweep less than a full turn");
		m.angle = m.sweep_end;
		r.whiskers.push_back(m);
	}
	for (const auto& s : cfg.sectionsInOrder())
	{
		if (s.rfind("whisker_", 0) != 0) continue;
		const long i = core::sectionIndex(s, "whisker_", n);
		if (i < 0)
			throw core::Error(core::iniWhere(cfg, s) + "[" + s + "]: not whisker_0 .. whisker_" + std::to_string(n - 1) +
							  " (whisker_count=" + std::to_string(n) + ", no leading zeros)");
	}
	return r;
}

obs::CObservationWhiskerContacts::Ptr Robot::blankSweep(
	const obs::TSensorNoise& noise, mrpt::Clock::time_point stamp) const
{
	auto o = std::make_shared<obs::CObservationWhiskerContacts>();
	o->timestamp = stamp;
	o->sensorLabel = "WHISKERS";
	o->sensorPose = sensorPose;
	o->noise = noise;
	o->whiskers = whiskers;
	for (auto& w : o->whiskers)
	{
		w.touched = false;
		w.angle = w.sweep_end;
		w.r = w.normal = w.texture = 0;
	}
	return o;
}
}  // namespace whiskermap::world

#include <whiskermap/core/Angles.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/world/ContactLogFormat.h>
#include <whiskermap/world/ContactLogWriter.h>

#include <cstdio>
#include <filesystem>

namespace whiskermap::world
{
namespace fs = std::filesystem;
using Format = ContactLogFormat;

ContactLogWriter::ContactLogWriter(const std::string& path, const std::string& source)
	: m_path(path), m_source(source)
{
	m_out.open(m_path + ".tmp", std::ios::binary);
	if (!m_out) throw core::Error(m_path + ": cannot create file (does its folder exist?)");
}

ContactLogWriter::~ContactLogWriter()
{
	if (m_closed) return;
	m_out.close();
	std::error_code ec;
	fs::remove(m_path + ".tmp", ec);
}

namespace
{
std::string g(double v)
{
	char b[32];
	std::snprintf(b, sizeof(b), "%g", v);
	return b;
}
}  // namespace

void ContactLogWriter::writeHeader(const obs::CObservationWhiskerContacts& first)
{
	using core::rad2deg;
	const auto& p = first.sensorPose;
	const auto& n = first.noise;
	m_out << Format::FIRST_LINE << "\n# exported from " << m_source << "\n# sensor '"
		  << first.sensorLabel << "': " << first.whiskers.size()
		  << " whiskers; sensor pose on the robot x=" << g(p.x()) << " m, y=" << g(p.y())
		  << " m, yaw=" << g(rad2deg(p.yaw())) << " deg\n"
		  << "# noise (for whisker-import --noise): sigma_r=" << g(n.sigma_r)
		  << " m, sigma_phi_deg=" << g(rad2deg(n.sigma_phi)) << ", sigma_tau=" << g(n.sigma_tau)
		  << "\n# mountings (for whisker-import --robot), whisker: mount_x, mount_y, "
			 "sweep_start_deg, sweep_end_deg, length\n";
	for (size_t i = 0; i < first.whiskers.size(); i++)
	{
		const auto& w = first.whiskers[i];
		m_out << "#   " << i << ": " << g(w.mount_x) << ", " << g(w.mount_y) << ", "
			  << g(rad2deg(w.sweep_start)) << ", " << g(rad2deg(w.sweep_end)) << ", " << g(w.length)
			  << "\n";
	}
	for (size_t c = 0; c < Format::COLUMNS.size(); c++)
		m_out << (c ? "," : "") << Format::COLUMNS[c];
	m_out << "\n";
}

void ContactLogWriter::checkSameSensor(const obs::CObservationWhiskerContacts& s) const
{
	auto fail = [&](const std::string& what)
	{
		throw core::Error(
			m_source + ": sweep " + std::to_string(m_sweeps) + ": " + what +
			" differs from the first sweep's: a contact log holds one sensor (one robot .ini, one "
			"noise preset)");
	};
	const auto& f = m_first;
	if (s.sensorLabel != f.sensorLabel) fail("the sensor label");
	// Exact comparisons (CPose3D's own == allows a tolerance on the rotation).
	if (s.sensorPose.m_coords != f.sensorPose.m_coords ||
		s.sensorPose.getRotationMatrix() != f.sensorPose.getRotationMatrix())
		fail("the sensor pose");
	if (s.noise.sigma_r != f.noise.sigma_r || s.noise.sigma_phi != f.noise.sigma_phi ||
		s.noise.sigma_tau != f.noise.sigma_tau)
		fail("the noise");
	if (s.whiskers.size() != f.whiskers.size()) fail("the whisker count");
	for (size_t i = 0; i < s.whiskers.size(); i++)
	{
		const auto &a = s.whiskers[i], &b = f.whiskers[i];
		if (a.mount_x != b.mount_x || a.mount_y != b.mount_y || a.sweep_start != b.sweep_start ||
			a.sweep_end != b.sweep_end || a.length != b.length)
			fail("whisker " + std::to_string(i) + "'s mounting");
	}
}

void ContactLogWriter::write(
	const mrpt::poses::CPose2D& odometry, const obs::CObservationWhiskerContacts& sweep)
{
	const std::string at = m_source + ": sweep " + std::to_string(m_sweeps) + ": ";
	if (sweep.timestamp.time_since_epoch().count() < 0)
		throw core::Error(at + "its timestamp is before 1601");
	if (m_sweeps > 0 && sweep.timestamp < m_lastTime)
		throw core::Error(at + "time goes backwards (a contact log needs sweeps in time order)");
	if (m_sweeps == 0)
	{
		m_first = sweep;
		writeHeader(sweep);
	}
	else
		checkSameSensor(sweep);
	m_lastTime = sweep.timestamp;

	std::string prefix;
	Format::appendTime(prefix, sweep.timestamp);
	prefix += ',';
	Format::appendNumber(prefix, odometry.x());
	prefix += ',';
	Format::appendNumber(prefix, odometry.y());
	prefix += ',';
	Format::appendDegrees(prefix, odometry.phi());
	prefix += ',';
	for (size_t i = 0; i < sweep.whiskers.size(); i++)
	{
		const auto& w = sweep.whiskers[i];
		m_row = prefix;
		m_row += std::to_string(i);
		m_row += w.touched ? ",1," : ",0,";
		Format::appendDegrees(m_row, w.angle);
		m_row += ',';
		Format::appendNumber(m_row, w.r);
		m_row += ',';
		Format::appendDegrees(m_row, w.normal);
		m_row += ',';
		Format::appendNumber(m_row, w.texture);
		m_row += '\n';
		m_out << m_row;
	}
	m_rows += sweep.whiskers.size();
	m_sweeps++;
}

void ContactLogWriter::close()
{
	if (m_sweeps == 0) throw core::Error(m_source + ": holds no whisker sweeps, nothing to export");
	m_out.close();
	if (!m_out) throw core::Error(m_path + ": write failed");
	fs::rename(m_path + ".tmp", m_path);
	m_closed = true;
}
}  // namespace whiskermap::world

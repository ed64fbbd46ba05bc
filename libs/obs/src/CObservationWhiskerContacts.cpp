#include <mrpt/serialization/CArchive.h>
#include <whiskermap/core/Angles.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/obs/CObservationWhiskerContacts.h>

#include <algorithm>
#include <cmath>
#include <sstream>

using namespace whiskermap::obs;

IMPLEMENTS_SERIALIZABLE(CObservationWhiskerContacts, CObservation, whiskermap::obs)

namespace
{
constexpr double MAX_LENGTH = 10.0;  // metres: no whisker is longer
constexpr double ANGLE_TOL = 1e-9;
constexpr double MAX_ANGLE = 1e3;  // radians (angles), and texture: any sane value is far below

void writeWhisker(mrpt::serialization::CArchive& out, const TWhisker& w)
{
	out << w.mount_x << w.mount_y << w.sweep_start << w.sweep_end << w.length << w.touched
		<< w.angle << w.r << w.normal << w.texture;
}
void readWhisker(mrpt::serialization::CArchive& in, TWhisker& w)
{
	in >> w.mount_x >> w.mount_y >> w.sweep_start >> w.sweep_end >> w.length;
	const auto touched = in.ReadAs<uint8_t>();  // a bool byte other than 0 or 1 is refused
	if (touched > 1) throw whiskermap::core::Error("CObservationWhiskerContacts: bool byte " + std::to_string(touched) + " is not 0 or 1");
	w.touched = touched == 1;
	in >> w.angle >> w.r >> w.normal >> w.texture;
}
/** The sensor label, its length bounded before anything is allocated. */
std::string readLabel(mrpt::serialization::CArchive& in)
{
	const auto n = in.ReadAs<uint32_t>();
	if (n > CObservationWhiskerContacts::MAX_LABEL)
		throw whiskermap::core::Error(
			"CObservationWhiskerContacts: stored sensor label length " + std::to_string(n) + " is not in [0, " +
			std::to_string(CObservationWhiskerContacts::MAX_LABEL) + "]");
	std::string s(n, '\0');
	if (n) in.ReadBuffer(s.data(), n);
	for (const char c : s)
		if (c < 0x20 || c > 0x7e) throw whiskermap::core::Error("CObservationWhiskerContacts: sensor label holds a non-printable byte");
	return s;
}
}  // namespace

uint8_t CObservationWhiskerContacts::serializeGetVersion() const { return 0; }

void CObservationWhiskerContacts::serializeTo(mrpt::serialization::CArchive& out) const
{
	out << timestamp << sensorLabel << sensorPose;
	out << noise.sigma_r << noise.sigma_phi << noise.sigma_tau;
	out.WriteAs<uint32_t>(whiskers.size());
	for (const auto& w : whiskers) writeWhisker(out, w);
}

void CObservationWhiskerContacts::serializeFrom(
	mrpt::serialization::CArchive& in, uint8_t version)
{
	switch (version)
	{
		case 0:
		{
			in >> timestamp;
			sensorLabel = readLabel(in);
			in >> sensorPose;
			in >> noise.sigma_r >> noise.sigma_phi >> noise.sigma_tau;
			const auto n = in.ReadAs<uint32_t>();
			if (n == 0 || n > MAX_WHISKERS)
				throw whiskermap::core::Error(
					"CObservationWhiskerContacts: stored whisker count " + std::to_string(n) +
					" is not in [1, " + std::to_string(MAX_WHISKERS) + "]");
			whiskers.resize(n);
			for (auto& w : whiskers) readWhisker(in, w);
			validate();
		}
		break;
		default:
			MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
	}
}

void CObservationWhiskerContacts::validate() const
{
	const bool printable = sensorLabel.size() <= MAX_LABEL &&
		std::all_of(sensorLabel.begin(), sensorLabel.end(), [](char c) { return c >= 0x20 && c <= 0x7e; });
	const std::string who = "CObservationWhiskerContacts" + (printable ? " '" + sensorLabel + "'" : std::string());
	auto fail = [&](const std::string& what) { throw whiskermap::core::Error(who + ": " + what); };
	if (!printable) fail("sensor label is longer than " + std::to_string(MAX_LABEL) + " characters or not printable ASCII");
	if (whiskers.empty() || whiskers.size() > MAX_WHISKERS)
		fail("whisker count " + std::to_string(whiskers.size()) + " is not in [1, " +
			 std::to_string(MAX_WHISKERS) + "]");
	const double sigmaMax[3] = {1.0, 2 * M_PI, 1.0};  // sigma_r (m), sigma_phi (rad), sigma_tau
	const double sigmas[3] = {noise.sigma_r, noise.sigma_phi, noise.sigma_tau};
	for (int k = 0; k < 3; k++)
		if (!(sigmas[k] >= 0 && sigmas[k] <= sigmaMax[k]))
			fail("noise std-dev " + std::to_string(sigmas[k]) + " is not in [0, " + std::to_string(sigmaMax[k]) + "]");
	for (double v : {sensorPose.x(), sensorPose.y(), sensorPose.z()})
		if (!(std::abs(v) <= MAX_LENGTH)) fail("sensor pose is not within 10 m of the robot");
	for (size_t i = 0; i < whiskers.size(); i++)
	{
		const auto& w = whiskers[i];
		const std::string at = "whisker " + std::to_string(i) + ": ";
		for (double v : {w.mount_x, w.mount_y, w.sweep_start, w.sweep_end, w.length, w.angle, w.r,
						 w.normal, w.texture})
			if (!std::isfinite(v)) fail(at + "non-finite value (NaN or inf)");
		for (double v : {w.sweep_start, w.sweep_end, w.angle, w.normal, w.texture})
			if (std::abs(v) > MAX_ANGLE) fail(at + "value " + std::to_string(v) + " is beyond +-1000");
		if (std::abs(w.mount_x) > MAX_LENGTH || std::abs(w.mount_y) > MAX_LENGTH || std::abs(w.r) > MAX_LENGTH)
			fail(at + "mount or range beyond 10 m");
		if (w.length <= 0 || w.length > MAX_LENGTH)
			fail(at + "length " + std::to_string(w.length) + " m is not in (0, 10]");
		const double lo = std::min(w.sweep_start, w.sweep_end);
		const double hi = std::max(w.sweep_start, w.sweep_end);
		if (w.angle < lo - ANGLE_TOL || w.angle > hi + ANGLE_TOL)
			fail(at + "angle " + std::to_string(w.angle) + " rad is outside its sweep");
		if (!w.touched) continue;
		if (w.r < 0) fail(at + "negative range r=" + std::to_string(w.r));
		if (w.r > w.length)
			fail(at + "range r=" + std::to_string(w.r) + " past the whisker length " +
				 std::to_string(w.length));
		if (w.texture < 0 || w.texture > 1)
			fail(at + "texture " + std::to_string(w.texture) + " is not in [0, 1]");
	}
}

std::vector<Shapelet> CObservationWhiskerContacts::toShapelets(
	const mrpt::poses::CPose2D& robotPose) const
{
	const mrpt::poses::CPose3D sensorInWorld = mrpt::poses::CPose3D(robotPose) + sensorPose;
	std::vector<Shapelet> out;
	for (size_t i = 0; i < whiskers.size(); i++)
	{
		const auto& w = whiskers[i];
		if (!w.touched) continue;
		double gx, gy, gz;
		sensorInWorld.composePoint(
			w.mount_x + w.r * std::cos(w.angle), w.mount_y + w.r * std::sin(w.angle), 0.0, gx, gy,
			gz);
		const double shaft = sensorInWorld.yaw() + w.angle;
		out.push_back(Shapelet{
			gx, gy, whiskermap::core::wrapToPi(sensorInWorld.yaw() + w.normal), w.texture,
			static_cast<int>(i), std::cos(shaft), std::sin(shaft)});
	}
	return out;
}

std::vector<SweptSector> CObservationWhiskerContacts::toSweptSectors(const mrpt::poses::CPose2D& robotPose) const
{
	const mrpt::poses::CPose3D sensorInWorld = mrpt::poses::CPose3D(robotPose) + sensorPose;
	std::vector<SweptSector> out;
	for (const auto& w : whiskers)
	{
		const double stop = w.touched ? w.angle : w.sweep_end;
		if (stop == w.sweep_start) continue;
		double px, py, pz;
		sensorInWorld.composePoint(w.mount_x, w.mount_y, 0, px, py, pz);
		// Counter-clockwise from the smaller angle.
		out.push_back(SweptSector{
			px, py, w.length, sensorInWorld.yaw() + std::min(w.sweep_start, stop), std::abs(stop - w.sweep_start)});
	}
	return out;
}

size_t CObservationWhiskerContacts::contactCount() const
{
	size_t n = 0;
	for (const auto& w : whiskers) n += w.touched ? 1 : 0;
	return n;
}

void CObservationWhiskerContacts::getDescriptionAsText(std::ostream& o) const
{
	CObservation::getDescriptionAsText(o);
	o << "Whisker sweep: " << whiskers.size() << " whiskers, " << contactCount()
	  << " contacts\n";
	o << "Sensor pose on robot: " << sensorPose << "\n";
	o << "Noise std-devs: sigma_r=" << noise.sigma_r << " m, sigma_phi=" << noise.sigma_phi
	  << " rad, sigma_tau=" << noise.sigma_tau << "\n";
	o << " #  mount_x  mount_y  sweep[deg]        length  touched  angle[deg]  r[m]    "
		 "normal[deg]  texture\n";
	for (size_t i = 0; i < whiskers.size(); i++)
	{
		const auto& w = whiskers[i];
		char line[256];
		std::snprintf(
			line, sizeof(line),
			"%2zu  %7.3f  %7.3f  %6.1f..%-6.1f  %6.3f  %-7s  %10.2f  %6.4f  %11.2f  %7.3f\n", i,
			w.mount_x, w.mount_y, whiskermap::core::rad2deg(w.sweep_start),
			whiskermap::core::rad2deg(w.sweep_end), w.length, w.touched ? "yes" : "no",
			whiskermap::core::rad2deg(w.angle), w.r, whiskermap::core::rad2deg(w.normal),
			w.texture);
		o << line;
	}
}

std::string CObservationWhiskerContacts::exportTxtHeader() const
{
	std::ostringstream s;
	for (size_t i = 0; i < whiskers.size(); i++)
		s << "TOUCHED_" << i << " ANGLE_" << i << " R_" << i << " NORMAL_" << i << " TEXTURE_"
		  << i << " ";
	return s.str();
}

std::string CObservationWhiskerContacts::exportTxtDataRow() const
{
	std::ostringstream s;
	s.precision(9);
	for (const auto& w : whiskers)
		s << (w.touched ? 1 : 0) << " " << w.angle << " " << w.r << " " << w.normal << " "
		  << w.texture << " ";
	return s.str();
}

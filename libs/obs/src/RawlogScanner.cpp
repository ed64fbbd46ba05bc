#include <whiskermap/core/Error.h>
#include <whiskermap/obs/CObservationWhiskerContacts.h>
#include <whiskermap/obs/RawlogScanner.h>

#include <cmath>
#include <cstring>
#include <sstream>

namespace whiskermap::obs
{
namespace
{
constexpr uint8_t END_FLAG = 0x88;  // MRPT's end-of-object byte
constexpr double ANY = 1e3;  // bound of angles and other unconstrained values

/** A problem with the object being read (wrapped with the file and object by next()). */
struct Problem
{
	std::string what;
};

std::string num(double v)
{
	std::ostringstream s;
	s << v;
	return s.str();
}

/** Reads an object's bytes into a buffer as it checks them. */
class Parser
{
   public:
	Parser(ByteSource& in, std::vector<uint8_t>& buf) : m_in(in), m_buf(buf) {}

	size_t pos() const { return m_buf.size(); }

	/** Appends n bytes; false when the data ended before the first of them (`atStart`). */
	bool take(size_t n, bool atStart = false)
	{
		if (n > RawlogScanner::MAX_OBJECT_BYTES - m_buf.size())
			throw Problem{"object larger than " + std::to_string(RawlogScanner::MAX_OBJECT_BYTES >> 20) + " MiB"};
		const size_t old = m_buf.size();
		m_buf.resize(old + n);
		const size_t got = m_in.read(m_buf.data() + old, n);
		if (got == 0 && atStart) return false;
		if (got < n) throw Problem{"truncated file (an object is cut off)"};
		return true;
	}
	template <class T>
	T raw()
	{
		take(sizeof(T));
		T v;
		std::memcpy(&v, m_buf.data() + m_buf.size() - sizeof(T), sizeof(T));
		return v;
	}
	uint8_t u8() { return raw<uint8_t>(); }
	bool boolean(const char* field)
	{
		const uint8_t b = u8();
		if (b > 1) throw Problem{std::string(field) + ": bool byte " + std::to_string(b) + " is not 0 or 1"};
		return b == 1;
	}
	uint32_t u32(const char* field, uint32_t lo, uint32_t hi)
	{
		const auto v = raw<uint32_t>();
		if (v < lo || v > hi)
			throw Problem{std::string(field) + ": " + std::to_string(v) + " is not in [" + std::to_string(lo) + ", " +
						  std::to_string(hi) + "]"};
		return v;
	}
	template <class T>
	double real(const std::string& field, double lo, double hi)
	{
		const double v = raw<T>();
		if (!std::isfinite(v)) throw Problem{field + ": non-finite value (NaN or inf)"};
		if (v < lo || v > hi) throw Problem{field + ": " + num(v) + " is not in [" + num(lo) + ", " + num(hi) + "]"};
		return v;
	}
	double f64(const std::string& field, double lo = -ANY, double hi = ANY) { return real<double>(field, lo, hi); }
	double f32(const std::string& field, double lo = -ANY, double hi = ANY) { return real<float>(field, lo, hi); }
	/** A sensor label: at most 256 printable ASCII characters. */
	void label()
	{
		const uint32_t n = u32("sensor label length", 0, 256);
		take(n);
		for (size_t i = m_buf.size() - n; i < m_buf.size(); i++)
			if (m_buf[i] < 0x20 || m_buf[i] > 0x7e) throw Problem{"sensor label holds a non-printable byte"};
	}
	/** An object header: returns the class name and checks the version. */
	std::string header(uint8_t& version, bool atStart = false)
	{
		if (!take(1, atStart)) return {};
		const uint8_t b = m_buf.back();
		if (!(b & 0x80)) throw Problem{"not an MRPT object header (old pre-0.5.5 format, or not a rawlog)"};
		const size_t n = b & 0x7f;
		if (n == 0 || n > 120) throw Problem{"class name length " + std::to_string(n) + " is not in [1, 120]"};
		take(n);
		std::string name(m_buf.end() - static_cast<std::ptrdiff_t>(n), m_buf.end());
		for (const char c : name)
			if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == ':'))
				throw Problem{"class name holds a byte that is not a letter, digit, '_' or ':'"};
		if (name == "nullptr") throw Problem{"a null object"};
		version = u8();
		return name;
	}
	void expectVersion(const std::string& cls, uint8_t version, uint8_t expected)
	{
		if (version != expected)
			throw Problem{cls + ": serialization version " + std::to_string(version) + " (MRPT 2.5.8 writes " +
						  std::to_string(expected) + ")"};
	}
	void end(const std::string& cls)
	{
		if (u8() != END_FLAG) throw Problem{cls + ": end-of-object flag missing (a bad length or layout)"};
	}

   private:
	ByteSource& m_in;
	std::vector<uint8_t>& m_buf;
};

const std::string POSE2D = "mrpt::poses::CPose2D", POSE3D = "mrpt::poses::CPose3D",
				  ODOMETRY = "mrpt::obs::CObservationOdometry", WHISKERS = "whiskermap::obs::CObservationWhiskerContacts",
				  ACTIONS = "mrpt::obs::CActionCollection", MOVEMENT = "mrpt::obs::CActionRobotMovement2D",
				  FRAME = "mrpt::obs::CSensoryFrame";

std::string shortName(const std::string& cls) { return cls.substr(cls.rfind(':') + 1); }

/** A nested object of exactly class `cls`. */
void nested(Parser& p, const std::string& field, const std::string& cls, uint8_t version)
{
	uint8_t v = 0;
	const std::string name = p.header(v);
	if (name != cls) throw Problem{field + ": class " + name + " where " + shortName(cls) + " belongs"};
	p.expectVersion(shortName(cls), v, version);
}

mrpt::poses::CPose2D pose2D(Parser& p, const std::string& field)
{
	nested(p, field, POSE2D, 1);
	const double b = RawlogScanner::MAX_COORDINATE;
	const double x = p.f64(field + " x", -b, b), y = p.f64(field + " y", -b, b), phi = p.f64(field + " phi");
	p.end(field);
	return {x, y, phi};
}

void pose3D(Parser& p, const std::string& field)
{
	nested(p, field, POSE3D, 3);
	for (const char* c : {" x", " y", " z"}) p.f64(field + c, -10, 10);  // metres on the robot
	double R[9];
	for (double& r : R) r = p.f64(field + " rotation", -1.000001, 1.000001);
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++)
		{
			const double dot = R[i] * R[j] + R[3 + i] * R[3 + j] + R[6 + i] * R[6 + j];
			if (std::abs(dot - (i == j)) > 1e-6) throw Problem{field + ": rotation matrix is not orthonormal"};
		}
	p.end(field);
}

mrpt::poses::CPose2D odometry(Parser& p)
{
	const auto pose = pose2D(p, "odometry");
	p.label();
	p.raw<uint64_t>();  // timestamp
	if (p.boolean("hasEncodersInfo")) p.raw<int32_t>(), p.raw<int32_t>();
	if (p.boolean("hasVelocities"))
		for (int k = 0; k < 3; k++) p.f64("velocityLocal", -1e6, 1e6);
	return pose;
}

void whiskers(Parser& p)
{
	p.raw<uint64_t>();  // timestamp
	p.label();
	pose3D(p, "sensorPose");
	p.f64("sigma_r", 0, 1);
	p.f64("sigma_phi", 0, 2 * M_PI);
	p.f64("sigma_tau", 0, 1);
	const uint32_t n = p.u32("whisker count", 1, static_cast<uint32_t>(CObservationWhiskerContacts::MAX_WHISKERS));
	for (uint32_t i = 0; i < n; i++)
	{
		const std::string w = "whisker " + std::to_string(i) + " ";
		p.f64(w + "mount_x", -10, 10), p.f64(w + "mount_y", -10, 10);
		p.f64(w + "sweep_start"), p.f64(w + "sweep_end");
		p.f64(w + "length", 0, 10);
		p.boolean("touched");
		p.f64(w + "angle"), p.f64(w + "r", -10, 10), p.f64(w + "normal"), p.f64(w + "texture");
	}
}

/** Returns the raw odometry increment (CActionRobotMovement2D version 7). */
mrpt::poses::CPose2D movement(Parser& p)
{
	const uint32_t method = p.raw<uint32_t>();
	if (method != 0) throw Problem{"estimation method " + std::to_string(method) + " (only 0, odometry, is read)"};
	const auto increment = pose2D(p, "raw odometry increment");
	p.u32("motion model", 0, 1);  // Gaussian or Thrun
	for (int k = 0; k < 6; k++) p.f32("Gaussian model parameter", 0, 1e6);
	p.u32("Thrun model particle count", 0, 10000);
	for (int k = 0; k < 6; k++) p.f32("Thrun model parameter", 0, 1e6);
	if (p.boolean("hasVelocities"))
		for (int k = 0; k < 3; k++) p.f64("velocityLocal", -1e6, 1e6);
	if (p.boolean("hasEncodersInfo")) p.raw<int32_t>(), p.raw<int32_t>();
	p.raw<uint64_t>();  // timestamp
	return increment;
}

/** The body of a top-level (or sensory-frame) object of class `cls`. */
void body(Parser& p, const std::string& cls, uint8_t version, size_t start, RawlogScanner::Object& o, bool topLevel)
{
	using Item = RawlogScanner::Item;
	const std::string name = shortName(cls);
	if (cls == ODOMETRY)
	{
		p.expectVersion(name, version, 2);
		o.items.push_back({Item::AbsolutePose, odometry(p), 0, 0});
		p.end(name);
	}
	else if (cls == WHISKERS)
	{
		p.expectVersion(name, version, 0);
		whiskers(p);
		p.end(name);
		o.items.push_back({Item::Sweep, {}, start, p.pos() - start});
	}
	else if (topLevel && cls == ACTIONS)
	{
		p.expectVersion(name, version, 0);
		const uint32_t n = p.u32("action count", 0, 64);
		for (uint32_t k = 0; k < n; k++)
		{
			nested(p, "action " + std::to_string(k), MOVEMENT, 7);
			const auto inc = movement(p);
			p.end(shortName(MOVEMENT));
			if (k == 0) o.items.push_back({Item::Increment, inc, 0, 0});
		}
		p.end(name);
	}
	else if (topLevel && cls == FRAME)
	{
		p.expectVersion(name, version, 2);
		const uint32_t n = p.u32("observation count", 0, 256);
		for (uint32_t k = 0; k < n; k++)
		{
			const size_t at = p.pos();
			uint8_t v = 0;
			const std::string inner = p.header(v);
			if (inner != ODOMETRY && inner != WHISKERS)
				throw Problem{"observation " + std::to_string(k) + " has class " + inner + ", which whiskermap does not read"};
			body(p, inner, v, at, o, false);
		}
		p.end(name);
	}
	else
		throw Problem{
			"class " + cls +
			", which whiskermap does not read (it reads CObservationOdometry, CObservationWhiskerContacts, "
			"CSensoryFrame and CActionCollection of CActionRobotMovement2D)"};
}
}  // namespace

RawlogScanner::RawlogScanner(ByteSource& in, std::string label) : m_in(in), m_label(std::move(label)) {}

bool RawlogScanner::next(Object& out)
{
	out.bytes.clear();
	out.items.clear();
	Parser p(m_in, out.bytes);
	try
	{
		uint8_t version = 0;
		out.className = p.header(version, true);
		if (out.className.empty()) return false;
		body(p, out.className, version, 0, out, true);
	}
	catch (const Problem& e)
	{
		throw core::Error(m_label + ": corrupt rawlog at object #" + std::to_string(m_objects) + ": " + e.what);
	}
	m_objects++;
	return true;
}
}  // namespace whiskermap::obs

#include <mrpt/io/CMemoryStream.h>
#include <mrpt/serialization/CArchive.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/core/conciseMessage.h>
#include <whiskermap/obs/RawlogReader.h>

#include <algorithm>
#include <cmath>

namespace whiskermap::obs
{
namespace
{
/** Deserializes the checked bytes of one sweep; it must use exactly those bytes. */
CObservationWhiskerContacts::Ptr deserialize(const uint8_t* data, size_t size)
{
	mrpt::io::CMemoryStream m;
	m.assignMemoryNotOwn(data, size);
	auto arch = mrpt::serialization::archiveFrom(m);
	auto obj = arch.ReadObject();
	auto sweep = std::dynamic_pointer_cast<CObservationWhiskerContacts>(obj);
	if (!sweep || m.getPosition() != size) throw core::Error("sweep bytes do not match their checked layout");
	return sweep;
}
}  // namespace

RawlogReader::RawlogReader(const std::string& path)
	: RawlogReader([path] { return ByteSource::file(path); }, path)
{
}

RawlogReader::RawlogReader(std::function<std::unique_ptr<ByteSource>()> open, std::string label)
	: m_open(std::move(open)), m_label(std::move(label))
{
	// Pass 1: everything checked, the summary gathered; nothing kept.
	m_src = m_open();
	m_scan = std::make_unique<RawlogScanner>(*m_src, m_label);
	Summary s;
	s.x0 = s.y0 = INFINITY, s.x1 = s.y1 = -INFINITY;
	Sweep sw;
	while (advance(sw))
	{
		s.sweepCount++;
		s.x0 = std::min(s.x0, sw.robotPose.x()), s.x1 = std::max(s.x1, sw.robotPose.x());
		s.y0 = std::min(s.y0, sw.robotPose.y()), s.y1 = std::max(s.y1, sw.robotPose.y());
		s.maxSigmaR = std::max(s.maxSigmaR, sw.obs->noise.sigma_r);
		for (const auto& w : sw.obs->whiskers)
			s.maxReach = std::max(s.maxReach, std::hypot(sw.obs->sensorPose.x() + w.mount_x, sw.obs->sensorPose.y() + w.mount_y) + w.length);
	}
	s.objects = m_scan->objects();
	s.actionSensoryFrameFormat = m_anyIncrement;
	if (s.objects == 0) throw core::Error(m_label + ": holds no objects, not a rawlog");
	if (s.sweepCount == 0) s.x0 = s.x1 = s.y0 = s.y1 = 0;
	m_summary = s;
	// Pass 2 starts afresh.
	m_scan.reset();
	m_src = m_open();
	m_scan = std::make_unique<RawlogScanner>(*m_src, m_label);
	m_obj = {};
	m_item = 0;
	m_pose.reset();
}

bool RawlogReader::next(Sweep& out) { return advance(out); }

bool RawlogReader::advance(Sweep& out)
{
	using Item = RawlogScanner::Item;
	for (;;)
	{
		if (m_item == m_obj.items.size())
		{
			if (!m_scan->next(m_obj)) return false;
			m_item = 0;
			continue;
		}
		const Item& it = m_obj.items[m_item++];
		const std::string where = m_label + ": object #" + std::to_string(m_scan->objects() - 1);
		if (it.kind == Item::AbsolutePose)
			m_pose = it.pose;
		else if (it.kind == Item::Increment)
		{
			m_anyIncrement = true;
			const auto p = (m_pose ? *m_pose : mrpt::poses::CPose2D()) + it.pose;
			const double b = RawlogScanner::MAX_COORDINATE;
			if (!(std::abs(p.x()) <= b && std::abs(p.y()) <= b))
				throw core::Error(where + ": the composed robot pose leaves the +-" + std::to_string(int(b)) + " m bound");
			m_pose = p;
		}
		else
		{
			if (!m_pose) throw core::Error(where + ": whisker sweep has no robot pose before it (no odometry or action)");
			try
			{
				out.obs = deserialize(m_obj.bytes.data() + it.offset, it.size);
			}
			catch (const std::exception& e)
			{
				throw core::Error(m_label + ": corrupt rawlog at object #" + std::to_string(m_scan->objects() - 1) + ": " +
								  core::conciseMessage(e));
			}
			out.robotPose = *m_pose;
			return true;
		}
	}
}

RawlogReader::Contents RawlogReader::read(const std::string& path)
{
	RawlogReader r(path);
	Contents c;
	static_cast<Summary&>(c) = r.summary();
	Sweep s;
	while (r.next(s)) c.sweeps.push_back(s);
	return c;
}

RawlogReader::Contents RawlogReader::forEach(const std::string& path, const std::function<void(const Sweep&)>& onSweep)
{
	RawlogReader r(path);
	Contents c;
	static_cast<Summary&>(c) = r.summary();
	Sweep s;
	while (r.next(s)) onSweep(s);
	return c;
}
}  // namespace whiskermap::obs

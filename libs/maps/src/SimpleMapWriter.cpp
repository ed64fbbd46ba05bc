#include <mrpt/io/CMemoryStream.h>
#include <mrpt/maps/CSimpleMap.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3DPDFGaussian.h>
#include <mrpt/serialization/CArchive.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/maps/SimpleMapWriter.h>

#include <cstring>
#include <vector>

namespace whiskermap::maps
{
namespace
{
/** The bytes before the entry count of a CSimpleMap as this MRPT writes it (class header
 *  and version), taken from an empty map: header, version, uint32 0, end flag. */
std::vector<uint8_t> simpleMapHeader()
{
	mrpt::io::CMemoryStream m;
	mrpt::serialization::archiveFrom(m) << mrpt::maps::CSimpleMap();
	const auto* p = static_cast<const uint8_t*>(m.getRawBufferData());
	const size_t n = m.getTotalBytesCount();
	const uint8_t tail[5] = {0, 0, 0, 0, 0x88};
	if (n < 5 || std::memcmp(p + n - 5, tail, 5) != 0)
		throw core::Error("this MRPT's CSimpleMap layout is not count + entries: cannot stream a .simplemap");
	return std::vector<uint8_t>(p, p + n - 5);
}
}  // namespace

SimpleMapWriter::SimpleMapWriter(const std::string& path, uint32_t entries) : m_path(path), m_expected(entries)
{
	if (!m_out.open(path)) throw core::Error(path + ": cannot create file");
	const auto header = simpleMapHeader();
	m_out.Write(header.data(), header.size());
	auto arch = mrpt::serialization::archiveFrom(m_out);
	arch << entries;
}

void SimpleMapWriter::add(const mrpt::poses::CPose2D& pose, const mrpt::obs::CObservation::Ptr& obs)
{
	mrpt::obs::CSensoryFrame sf;
	sf.insert(obs);
	add(pose, sf);
}

void SimpleMapWriter::add(const mrpt::poses::CPose2D& pose, const mrpt::obs::CSensoryFrame& sf)
{
	if (m_written == m_expected) throw core::Error(m_path + ": more entries than announced");
	const mrpt::poses::CPose3DPDFGaussian pdf{mrpt::poses::CPose3D(pose)};
	auto arch = mrpt::serialization::archiveFrom(m_out);
	arch << pdf << sf;
	m_written++;
}

void SimpleMapWriter::close()
{
	if (m_written != m_expected)
		throw core::Error(m_path + ": " + std::to_string(m_written) + " entries written, " + std::to_string(m_expected) + " announced");
	const uint8_t end = 0x88;
	m_out.Write(&end, 1);
	m_out.close();
}
}  // namespace whiskermap::maps

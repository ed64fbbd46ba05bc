#include <whiskermap/baseline/BatchInput.h>
#include <whiskermap/baseline/FreeSpace.h>

namespace whiskermap::baseline
{
BatchInput::BatchInput(const TBaselineParams& p)
	: m_contacts(p.leg_width, p.contacts_per_cell), m_sectors(FreeSpace::CELL, p.sectors_per_cell)
{
}

void BatchInput::add(const obs::RawlogReader::Sweep& sweep)
{
	for (const Contact& c : Contact::of(sweep, static_cast<uint32_t>(m_sweeps))) m_contacts.add(c.p.x(), c.p.y(), c);
	for (const obs::SweptSector& s : sweep.obs->toSweptSectors(sweep.robotPose)) m_sectors.add(s.x, s.y, s);
	m_sweeps++;
}
}  // namespace whiskermap::baseline

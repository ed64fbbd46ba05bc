#pragma once
#include <whiskermap/baseline/CellSample.h>
#include <whiskermap/baseline/Contact.h>
#include <whiskermap/baseline/TBaselineParams.h>
#include <whiskermap/obs/RawlogReader.h>
#include <whiskermap/obs/SweptSector.h>

#include <cstdint>
#include <vector>

namespace whiskermap::baseline
{
/** What the batch fit keeps of a run, sweep by sweep: its contacts and the sectors its
 *  whiskers swept, each a bounded sample per cell (CellSample; TBaselineParams
 *  contacts_per_cell, sectors_per_cell). A log of any length is streamed through it in
 *  memory bounded by the area it covers (doc/baseline.md, "Bounded memory"). */
class BatchInput
{
   public:
	explicit BatchInput(const TBaselineParams& p);

	void add(const obs::RawlogReader::Sweep& sweep);

	/** The contacts kept, in rawlog order (every contact while no cell is full). */
	std::vector<Contact> contacts() const { return m_contacts.items(); }
	/** The swept sectors kept, in rawlog order. */
	std::vector<obs::SweptSector> sectors() const { return m_sectors.items(); }

	uint64_t sweeps() const { return m_sweeps; }
	uint64_t contactsSeen() const { return m_contacts.seen(); }

   private:
	uint64_t m_sweeps = 0;
	CellSample<Contact> m_contacts;
	CellSample<obs::SweptSector> m_sectors;
};
}  // namespace whiskermap::baseline

#pragma once
#include <whiskermap/baseline/Contact.h>
#include <whiskermap/baseline/LegFit.h>
#include <whiskermap/baseline/TBaselineParams.h>

#include <vector>

namespace whiskermap::baseline
{
/** Finds the legs among a run's contacts (doc/baseline.md, steps 1-3):
 *  1. texture gate: contacts whose texture is more than texture_gate sigma_tau (+ floor)
 *     from the table texture are dropped (walls feel different);
 *  2. single-linkage clustering of the centres the contacts point at (half a leg width
 *     behind each contact), within link_distance leg widths + 2 sigma_r;
 *  3. a square leg fitted to each cluster (LegFit); a cluster that is not leg-shaped is
 *     split in two (2-means on the pointed centres) when its halves are leg-shaped and
 *     separated by a gap, else rejected; a leg whose mean texture is off is rejected. */
struct LegExtraction
{
	std::vector<LegFit> legs;
	size_t contactsUsed = 0;  ///< contacts past the texture gate
	size_t textureRejected = 0;  ///< contacts dropped by the texture gate
	size_t clustersRejected = 0;  ///< clusters (or parts) rejected: not leg-shaped or texture
	size_t contactsRejected = 0;  ///< contacts in them
	size_t splits = 0;  ///< clusters split in two

	static LegExtraction run(const std::vector<Contact>& contacts, const TBaselineParams& p);
};
}  // namespace whiskermap::baseline

#pragma once
#include <whiskermap/baseline/BatchInput.h>
#include <whiskermap/baseline/Contact.h>
#include <whiskermap/baseline/LegExtraction.h>
#include <whiskermap/baseline/TBaselineParams.h>
#include <whiskermap/baseline/TableEstimate.h>

#include <vector>

namespace whiskermap::baseline
{
/** The plain batch geometric fit a user would write instead of whiskermap's map (issue 7's
 *  baseline, doc/baseline.md): all contacts of a run at once, clustered into legs
 *  (LegExtraction), legs matched to the known table (TableMatcher), each table fitted to all
 *  its contacts. No priors beyond the known table, no sampling (beyond BatchInput's bounded
 *  sample of a very long log). */
struct BatchFit
{
	std::vector<Contact> contacts;  ///< the run's contacts (BatchInput::contacts), in rawlog order
	LegExtraction legs;
	std::vector<TableEstimate> tables;
	size_t proposals = 0, contradicted = 0;  ///< TableMatcher's counts

	static BatchFit run(const BatchInput& input, const TBaselineParams& p);
};
}  // namespace whiskermap::baseline

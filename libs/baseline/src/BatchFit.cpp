#include <whiskermap/baseline/BatchFit.h>
#include <whiskermap/baseline/FreeSpace.h>
#include <whiskermap/baseline/TableMatcher.h>

namespace whiskermap::baseline
{
BatchFit BatchFit::run(const BatchInput& input, const TBaselineParams& p)
{
	BatchFit f;
	f.contacts = input.contacts();
	f.legs = LegExtraction::run(f.contacts, p);
	const FreeSpace free(input.sectors());
	TableMatcher matcher(f.contacts, f.legs.legs, free, p);
	f.tables = matcher.run();
	f.proposals = matcher.proposals();
	f.contradicted = matcher.contradicted();
	return f;
}
}  // namespace whiskermap::baseline

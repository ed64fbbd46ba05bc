#include <whiskermap/baseline/BatchFit.h>
#include <whiskermap/baseline/FreeSpace.h>
#include <whiskermap/baseline/TableMatcher.h>

namespace whiskermap::baseline
{
BatchFit BatchFit::run(const std::vector<obs::RawlogReader::Sweep>& sweeps, const TBaselineParams& p)
{
	BatchFit f;
	for (size_t i = 0; i < sweeps.size(); i++)
	{
		const auto c = Contact::of(sweeps[i], uint32_t(i));
		f.contacts.insert(f.contacts.end(), c.begin(), c.end());
	}
	f.legs = LegExtraction::run(f.contacts, p);
	const FreeSpace free(sweeps);
	TableMatcher matcher(f.contacts, f.legs.legs, free, p);
	f.tables = matcher.run();
	f.proposals = matcher.proposals();
	f.contradicted = matcher.contradicted();
	return f;
}
}  // namespace whiskermap::baseline

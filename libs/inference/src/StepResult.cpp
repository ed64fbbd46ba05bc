#include <whiskermap/inference/StepResult.h>

#include <algorithm>

namespace whiskermap::inference
{
void addTallies(std::vector<MoveTally>& into, const std::vector<MoveTally>& from)
{
	for (size_t k = 0; k < from.size(); k++)
	{
		const MoveTally& t = from[k];
		// The same registry gives the same order: look at the same position first.
		auto it = k < into.size() && into[k].name == t.name
					  ? into.begin() + static_cast<long>(k)
					  : std::find_if(into.begin(), into.end(), [&](const MoveTally& o) { return o.name == t.name; });
		if (it == into.end()) it = into.insert(into.end(), MoveTally{t.name, 0, 0});
		it->proposed += t.proposed, it->accepted += t.accepted;
	}
}
}  // namespace whiskermap::inference

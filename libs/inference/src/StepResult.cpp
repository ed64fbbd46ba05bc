#include <whiskermap/inference/StepResult.h>

#include <algorithm>

namespace whiskermap::inference
{
void addTallies(std::vector<MoveTally>& into, const std::vector<MoveTally>& from)
{
	for (const MoveTally& t : from)
	{
		auto it = std::find_if(into.begin(), into.end(), [&](const MoveTally& o) { return o.name == t.name; });
		if (it == into.end()) it = into.insert(into.end(), MoveTally{t.name, 0, 0});
		it->proposed += t.proposed, it->accepted += t.accepted;
	}
}
}  // namespace whiskermap::inference

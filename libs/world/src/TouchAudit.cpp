#include <whiskermap/world/TouchAudit.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cstdint>

namespace whiskermap::world
{
TouchAudit TouchAudit::run(
	const World& world, const Robot& robot, const obs::TSensorNoise& noise, uint64_t seed,
	const std::vector<mrpt::poses::CPose2D>& path)
{
	WhiskerSimulator sim(world, robot, noise, seed);
	TouchAudit a;
	a.legsTouched.assign(world.tables.size(), {});
	std::vector<WhiskerSimulator::Truth> truth;
	for (const auto& p : path)
	{
		if (!sim.poseIsFree(p))
		{
			a.blockedPoses++;
			continue;
		}
		const auto sweep = sim.sense(p, mrpt::Clock::fromDouble(0), &truth);
		for (size_t i = 0; i < sweep->whiskers.size(); i++)
		{
			if (!sweep->whiskers[i].touched) continue;
			a.contacts.push_back(Label{truth[i].table, truth[i].leg});
			if (truth[i].table >= 0) a.legsTouched[truth[i].table].set(truth[i].leg);
		}
	}
	return a;
}

size_t TouchAudit::identifiable() const
{
	return std::count_if(
		legsTouched.begin(), legsTouched.end(), [](const auto& b) { return b.count() >= 2; });
}

int TouchAudit::fewestLegs() const
{
	int fewest = INT_MAX;
	for (const auto& b : legsTouched) fewest = std::min(fewest, int(b.count()));
	return legsTouched.empty() ? 0 : fewest;
}

size_t TouchAudit::closestCrossLegSpacing() const
{
	// Per table, the last index at which each leg was touched; a contact on leg k is compared
	// with the latest contact on every other leg of its table.
	std::vector<std::array<size_t, 4>> last(legsTouched.size());
	for (auto& l : last) l.fill(SIZE_MAX);
	size_t closest = SIZE_MAX;
	for (size_t j = 0; j < contacts.size(); j++)
	{
		const auto& c = contacts[j];
		if (c.table < 0) continue;
		for (int k = 0; k < 4; k++)
			if (k != c.leg && last[c.table][k] != SIZE_MAX) closest = std::min(closest, j - last[c.table][k]);
		last[c.table][c.leg] = j;
	}
	return closest;
}

size_t TouchAudit::tableContacts() const
{
	return std::count_if(contacts.begin(), contacts.end(), [](const Label& l) { return l.table >= 0; });
}
}  // namespace whiskermap::world

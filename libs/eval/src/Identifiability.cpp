#include <whiskermap/eval/Identifiability.h>

#include <algorithm>
#include <bitset>

namespace whiskermap::eval
{
double Identifiability::defaultGate(const std::vector<obs::RawlogReader::Sweep>& sweeps)
{
	double sigma = 0;
	for (const auto& s : sweeps) sigma = std::max(sigma, s.obs->noise.sigma_r);
	return 3 * sigma + 0.01;
}

Identifiability Identifiability::of(
	const world::World& world, const std::vector<obs::RawlogReader::Sweep>& sweeps, double gate)
{
	std::vector<std::bitset<4>> touched(world.tables.size());
	for (const auto& sweep : sweeps)
		for (const auto& s : sweep.obs->toShapelets(sweep.robotPose))
			for (size_t t = 0; t < world.tables.size(); t++)
				for (int k = 0; k < 4; k++)
					if (world.tables[t].leg(k, int(t)).distance({s.x, s.y}) <= gate)
						touched[t].set(k);
	Identifiability id;
	id.gate = gate;
	for (size_t t = 0; t < touched.size(); t++)
		if (touched[t].count() >= 2) id.tables.push_back(t);
	return id;
}

double Identifiability::recall(const MapEvaluation& e) const
{
	if (tables.empty()) return 1.0;
	const auto found = std::count_if(
		tables.begin(), tables.end(), [&](size_t t) { return e.truthMatch.at(t) >= 0; });
	return double(found) / double(tables.size());
}
}  // namespace whiskermap::eval

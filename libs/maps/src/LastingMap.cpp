#include <whiskermap/inference/RigidTableFit.h>
#include <whiskermap/maps/LastingMap.h>
#include <whiskermap/maps/LastingWorkspace.h>
#include <whiskermap/model/Posterior.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace whiskermap::maps
{
namespace
{
bool sameLeg(const model::Blackboard& a, const model::Blackboard& b, model::Id l)
{
	const model::Leg &p = a.leg(l), &q = b.leg(l);
	return p.x == q.x && p.y == q.y && p.theta == q.theta && p.parent == q.parent &&
		   a.evidence(l).count() == b.evidence(l).count() && a.shapeletsOf(l) == b.shapeletsOf(l);
}

/** Table t's rigid fit (its reported pose) depends only on which contacts its legs explain at
 *  which corners: true when the anneal left those as they were. */
bool sameFitData(const model::Blackboard& a, const model::Blackboard& b, model::Id t)
{
	if (!b.hasTable(t) || a.legsOf(t) != b.legsOf(t) || a.table(t).cls != b.table(t).cls) return false;
	for (const model::Id l : b.legsOf(t))
		if (a.leg(l).corner != b.leg(l).corner || a.leg(l).wx != b.leg(l).wx || a.leg(l).wy != b.leg(l).wy ||
			a.shapeletsOf(l) != b.shapeletsOf(l) || a.evidence(l).count() != b.evidence(l).count())
			return false;
	return true;
}

/** The sampler's settings with the lasting map's local schedule (to the sampler's beta_end). */
inference::SamplerParams localSampler(inference::SamplerParams p, const LastingMap::TOptions::TSchedule& s)
{
	const double end = p.schedule.betas().back();
	p.schedule = inference::AnnealingSchedule::geometric(std::min(s.beta_start, end), end, s.temperatures);
	p.sweeps_per_temperature = static_cast<int>(s.sweeps_per_temperature);
	p.coldest_sweeps = static_cast<int>(s.coldest_sweeps);
	p.polish_sweeps = static_cast<int>(s.polish_sweeps);
	return p;
}
}  // namespace

std::vector<double> LastingMap::existence(
	LastingWorkspace& ws, const model::Blackboard& start, const model::Blackboard& solved,
	const model::ModelParams& model, const inference::SamplerParams& sampler, uint64_t seed)
{
	auto& spread = ws.spread;
	// Where legs changed (came, went, moved, relinked, gained contacts): a table's existence
	// depends on its own legs and on the legs that could pair with them (TableExistence), so
	// only tables within a pair's reach of a change are scored again; the rest keep theirs.
	std::vector<std::pair<double, double>> changed;
	const model::Id bound = std::max(start.legIdBound(), solved.legIdBound());
	for (model::Id l = 0; l < bound; l++)
	{
		const bool was = start.hasLeg(l), is = solved.hasLeg(l);
		if (was && is && sameLeg(start, solved, l)) continue;
		if (was) changed.emplace_back(start.leg(l).x, start.leg(l).y);
		if (is) changed.emplace_back(solved.leg(l).x, solved.leg(l).y);
	}
	const double reach = std::hypot(model.table_length, model.table_width) + 3 * model.parent_gate;
	std::vector<double> out(static_cast<size_t>(solved.tableIdBound()), 0.0);
	spread.assign(out.size(), {});
	std::vector<model::Id> rescored;
	for (model::Id t = 0; t < solved.tableIdBound(); t++)
	{
		if (!solved.hasTable(t)) continue;
		bool same = t < static_cast<model::Id>(ws.region->tables.size()) && start.hasTable(t) &&
					start.legsOf(t) == solved.legsOf(t) && start.table(t).x == solved.table(t).x &&
					start.table(t).y == solved.table(t).y && start.table(t).theta == solved.table(t).theta;
		for (const model::Id l : solved.legsOf(t))
			for (const auto& [x, y] : changed)
				same = same && std::hypot(x - solved.leg(l).x, y - solved.leg(l).y) > reach;
		if (same)
		{
			out[static_cast<size_t>(t)] = m_state.existence(ws.region->tables[static_cast<size_t>(t)]);
			spread[static_cast<size_t>(t)] = m_state.chainSpread(ws.region->tables[static_cast<size_t>(t)]);
		}
		else
			rescored.push_back(t);
	}
	if (rescored.empty() || sampler.posterior_steps == 0)
	{
		for (const model::Id t : rescored) out[static_cast<size_t>(t)] = ws.existence.of(solved, t);
		return out;
	}
	// Issue 10's posterior: the fraction of the chain's samples holding each re-scored table.
	if (!ws.posterior) ws.posterior = std::make_unique<inference::PosteriorChain>(model, sampler);
	const long burnIn = sampler.posterior_steps / 5;
	const auto chain = ws.posterior->run(solved, seed ^ 0x5851F42D4C957F2DULL, burnIn, (sampler.posterior_steps - burnIn) / 5, 5);
	for (const model::Id t : rescored)
	{
		const auto& c = chain[static_cast<size_t>(t)];
		out[static_cast<size_t>(t)] = c.existence;
		if (c.existence > 0) spread[static_cast<size_t>(t)] = {c.sd_x, c.sd_y, c.sd_yaw};
	}
	return out;
}

std::vector<double> LastingMap::wallExistence(const model::Blackboard& solved)
{
	// P(W) = 1 / (1 + exp(-s_W)), s_W the wall's log-odds against its contacts' null cause (eq. 20).
	std::vector<double> out(static_cast<size_t>(solved.wallIdBound()), 0.0);
	for (model::Id w = 0; w < solved.wallIdBound(); w++)
		if (solved.hasWall(w)) out[static_cast<size_t>(w)] = model::annealedAcceptance(model::logOddsWall(solved, w), 1);
	return out;
}

void LastingMap::refitReported(LastingWorkspace& ws, const model::ModelParams& model)
{
	// Region tables whose fit data did not change keep their pose (refitting gives the same).
	std::vector<model::Id> kept;
	for (const auto& [b, pose] : ws.carry)
	{
		const model::Id t = ws.newTables[static_cast<size_t>(b)];
		if (t == model::NONE) continue;  // merged away (mergeOverlappingLegs)
		model::Table r = m_state.reported(t);
		r.x = pose.x, r.y = pose.y, r.theta = pose.theta;
		m_state.setReported(t, r);
		kept.push_back(t);
	}
	std::sort(kept.begin(), kept.end());
	ws.refit.insert(ws.refit.end(), ws.newTables.begin(), ws.newTables.end());
	for (const model::Id l : ws.newLegs)
		if (l != model::NONE) ws.refit.push_back(m_state.leg(l).parent);
	std::sort(ws.refit.begin(), ws.refit.end());
	ws.refit.erase(std::unique(ws.refit.begin(), ws.refit.end()), ws.refit.end());
	const model::ModelParams shaft = reportModel(model);
	for (const model::Id t : ws.refit)
		if (t != model::NONE && m_state.hasTable(t) && !std::binary_search(kept.begin(), kept.end(), t))
			m_state.setReported(t, inference::fitRigidTable(m_state, t, shaft));
}

inference::PoseSpread LastingMap::poseSpread(model::Id t, const model::ModelParams& model, uint64_t seed) const
{
	const model::ModelParams shaft = reportModel(model);
	return inference::rigidPoseSpread(m_state, t, inference::fitRigidTable(m_state, t, shaft), shaft, seed);
}

model::ModelParams LastingMap::reportModel(const model::ModelParams& model)
{
	model::ModelParams shaft = model;
	shaft.shaft_noise = true;  // the reading errs along its shaft (contacts without one: isotropic)
	return shaft;
}

LastingMap::TStats LastingMap::insert(
	const std::vector<obs::Shapelet>& contacts, const model::ModelParams& model,
	const inference::SamplerParams& sampler, uint64_t seed, const model::SweptGrid* grid)
{
	if (contacts.empty()) return {};
	if (m_pendingSweeps == 0) m_pendingFrom = m_state.nextSeq();
	for (const auto& s : contacts) m_state.addContact(s);
	if (++m_pendingSweeps < m_options.batch_sweeps) return {};
	return annealPending(model, sampler, seed, grid);
}

LastingMap::TStats LastingMap::annealPending(
	const model::ModelParams& model, const inference::SamplerParams& sampler, uint64_t seed, const model::SweptGrid* grid)
{
	if (m_pendingSweeps == 0) return {};
	m_pendingSweeps = 0;
	LastingWorkspace& ws = LastingWorkspace::local(model, sampler, m_options.schedule);
	// The pending contacts, in insertion order (a scan: small against the anneal).
	ws.fresh.clear();
	for (model::Id c = 0; c < m_state.contactIdBound(); c++)
		if (m_state.hasContact(c) && m_state.contact(c).seq >= m_pendingFrom) ws.fresh.push_back(c);
	std::sort(ws.fresh.begin(), ws.fresh.end(), [&](model::Id a, model::Id b) {
		return m_state.contact(a).seq < m_state.contact(b).seq;
	});
	TStats stats =
		solve(ws, model, localSampler(sampler, m_options.schedule), m_options.visit_radius, seed, grid, ws.sampler);
	if (model.cornersTighterThanReadings())
		for (uint32_t k = 0; k < m_options.noisy_revisions; k++)
		{
			TStats r;
			if (!reviseNext(ws, model, sampler, seed ^ (0x9E3779B97F4A7C15ULL * (k + 1)), grid, r)) continue;
			stats.revisions++;
			inference::addMoveCounts(stats.proposed, stats.accepted, stats.moveTypes, r);
		}
	return stats;
}

bool LastingMap::reviseNext(
	LastingWorkspace& ws, const model::ModelParams& model, const inference::SamplerParams& sampler, uint64_t seed,
	const model::SweptGrid* grid, TStats& out)
{
	// A scan of the stored contacts (bounded by contacts_per_leg a leg plus the unexplained
	// ones): linear in the map, small against the anneal that follows (not measured apart).
	constexpr uint64_t NO_SEQ = std::numeric_limits<uint64_t>::max();
	uint64_t next = NO_SEQ, oldest = NO_SEQ;
	model::Id pick = model::NONE, wrap = model::NONE;
	for (model::Id c = 0; c < m_state.contactIdBound(); c++)
	{
		if (!m_state.hasContact(c) || m_state.contact(c).leg == model::NONE) continue;
		const uint64_t s = m_state.contact(c).seq;
		if (s >= m_reviseSeq && s < next) next = s, pick = c;
		if (s < oldest) oldest = s, wrap = c;
	}
	if (pick == model::NONE) pick = wrap, m_reviseSeq = 0;  // past the newest: from the oldest again
	if (pick == model::NONE) return false;
	ws.fresh = m_state.contactsOf(m_state.contact(pick).leg);
	for (const model::Id c : ws.fresh) m_reviseSeq = std::max(m_reviseSeq, m_state.contact(c).seq + 1);
	// Every leg that could share a table with the revised one, every table that could hold it.
	out = solve(ws, model, sampler, std::max(m_options.visit_radius, model.maxDiagonal() + model.parent_gate), seed, grid, ws.reviser);
	return true;
}

LastingMap::TStats LastingMap::solve(
	LastingWorkspace& ws, const model::ModelParams& model, const inference::SamplerParams& sampler, double visit,
	uint64_t seed, const model::SweptGrid* grid, std::unique_ptr<inference::BlackboardSampler>& cache)
{
	TStats stats;
	// The local problem around the new contacts.
	model::LastingState::Radii radii;
	radii.visit = visit;
	radii.board = radii.visit + std::hypot(model.table_length, model.table_width) + 2 * model.parent_gate;
	radii.context = radii.board + std::hypot(model.table_length, model.table_width);
	if (!ws.region) ws.region = std::make_unique<model::LastingState::Region>(model);
	m_state.extract(ws.fresh, radii, model, *ws.region);
	ws.region->board.setSweptGrid(grid);
	const model::Blackboard& board = ws.region->board;

	if (!cache) cache = std::make_unique<inference::BlackboardSampler>(model, sampler);
	const inference::StepResult result = cache->anneal(board, seed);
	const model::Blackboard& solved = cache->best();

	ws.refit.clear();  // tables the region's legs stood under (a context table may lose or gain one)
	ws.carry.clear();  // region tables whose reported pose stands (board id, pose)
	if (m_options.rigid_pose)
	{
		for (const model::Id l : ws.region->legs)
			if (l != model::NONE && m_state.hasLeg(l)) ws.refit.push_back(m_state.leg(l).parent);
		for (model::Id b = 0; b < static_cast<model::Id>(ws.region->tables.size()); b++)
			if (sameFitData(board, solved, b))
				ws.carry.emplace_back(b, m_state.reported(ws.region->tables[static_cast<size_t>(b)]));
	}
	m_state.replace(*ws.region, solved, existence(ws, board, solved, model, sampler, seed), ws.newTables, ws.newLegs, wallExistence(solved), model);
	for (size_t b = 0; b < ws.newTables.size(); b++)
		if (ws.newTables[b] != model::NONE) m_state.setChainSpread(ws.newTables[b], ws.spread[b]);
	// No two legs in one place: the search may pass through overlaps (eq. 16 is soft), the
	// stored map may not (doc/map-plugin.md). The merged legs' tables are refitted.
	ws.merged.clear();
	if (m_state.mergeOverlappingLegs(ws.newLegs, ws.merged, ws.refit, m_options.leg_merge_gap) > 0)
	{
		for (model::Id& l : ws.newLegs)
			if (l != model::NONE && !m_state.hasLeg(l)) l = model::NONE;
		for (model::Id& t : ws.newTables)
			if (t != model::NONE && !m_state.hasTable(t)) t = model::NONE;
		for (const model::Id l : ws.merged)
			if (m_state.hasLeg(l))
			{
				m_state.fold(l, m_options.contacts_per_leg, model);
				ws.refit.push_back(m_state.leg(l).parent);
			}
	}
	for (const model::Id l : ws.newLegs)
		if (l != model::NONE) m_state.fold(l, m_options.contacts_per_leg, model);
	for (const model::Id c : ws.fresh)
		if (m_state.hasContact(c) && m_state.contact(c).leg == model::NONE)
			m_state.forgetUnexplained(c, m_options.unexplained_per_spot, model.leg_width);
	if (m_options.rigid_pose) refitReported(ws, model);

	for (model::Id t = 0; t < board.tableIdBound(); t++) stats.visited += board.hasTable(t) && !board.tableDormant(t);
	for (model::Id l = 0; l < board.legIdBound(); l++) stats.visited += board.hasLeg(l) && !board.legDormant(l);
	stats.boardHypotheses = static_cast<uint32_t>(board.tableCount() + board.legCount());
	stats.boardContacts = static_cast<uint32_t>(board.shapelets().size());
	stats.proposed = result.proposed;
	stats.accepted = result.accepted;
	stats.moveTypes = result.moveTypes;
	stats.changed = true;
	stats.initialLogPosterior = result.initialLogPosterior;
	stats.logPosterior = result.logPosterior;
	return stats;
}
}  // namespace whiskermap::maps

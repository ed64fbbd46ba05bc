#include <whiskermap/maps/LastingMap.h>

#include <cmath>

namespace whiskermap::maps
{
LastingMap::TStats LastingMap::insert(
	const std::vector<obs::Shapelet>& contacts, const model::ModelParams& model,
	const inference::SamplerParams& sampler, uint64_t seed)
{
	TStats stats;
	if (contacts.empty()) return stats;
	m_new.clear();
	for (const auto& s : contacts) m_new.push_back(m_state.addContact(s));

	// The local problem around the new contacts.
	model::LastingState::Radii radii;
	radii.visit = m_options.visit_radius;
	radii.board = radii.visit + std::hypot(model.table_length, model.table_width) + 2 * model.parent_gate;
	radii.context = radii.board + std::hypot(model.table_length, model.table_width);
	if (!m_region) m_region = std::make_unique<model::LastingState::Region>(model);
	m_state.extract(m_new, radii, model, *m_region);
	const model::Blackboard& board = m_region->board;

	if (!m_sampler || !(m_samplerModel == model))
	{
		m_sampler = std::make_unique<inference::BlackboardSampler>(model, sampler);
		m_samplerModel = model;
	}
	const inference::StepResult result = m_sampler->anneal(board, seed);
	const model::Blackboard& solved = m_sampler->best();

	m_state.replace(*m_region, solved, m_existence.of(solved), m_newTables, m_newLegs);
	for (const model::Id l : m_newLegs)
		if (l != model::NONE) m_state.fold(l, m_options.contacts_per_leg, model);
	for (const model::Id c : m_new)
		if (m_state.hasContact(c) && m_state.contact(c).leg == model::NONE)
			m_state.forgetUnexplained(c, m_options.unexplained_per_spot, model.leg_width);

	for (model::Id t = 0; t < board.tableIdBound(); t++) stats.visited += board.hasTable(t) && !board.tableDormant(t);
	for (model::Id l = 0; l < board.legIdBound(); l++) stats.visited += board.hasLeg(l) && !board.legDormant(l);
	stats.boardHypotheses = static_cast<uint32_t>(board.tableCount() + board.legCount());
	stats.boardContacts = static_cast<uint32_t>(board.shapelets().size());
	stats.proposed = result.proposed;
	stats.accepted = result.accepted;
	stats.changed = true;
	stats.initialLogPosterior = result.initialLogPosterior;
	stats.logPosterior = result.logPosterior;
	return stats;
}
}  // namespace whiskermap::maps

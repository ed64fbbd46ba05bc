#include <whiskermap/core/Error.h>
#include <whiskermap/slam/PathTree.h>

#include <algorithm>

namespace whiskermap::slam
{
void PathTree::reset(size_t particles, const mrpt::math::TPose2D& start)
{
	m_nodes.clear(), m_free.clear();
	const uint32_t root = make(start, NONE);
	m_nodes[root].refs = static_cast<uint32_t>(particles);
	m_leaf.assign(particles, root);
	m_settled = 0;
}

uint32_t PathTree::make(const mrpt::math::TPose2D& pose, uint32_t parent)
{
	uint32_t n;
	if (!m_free.empty())
		n = m_free.back(), m_free.pop_back();
	else
	{
		if (m_nodes.size() >= NONE) throw core::Error("PathTree: more than 2^32 - 1 poses alive");
		n = static_cast<uint32_t>(m_nodes.size());
		m_nodes.emplace_back();
	}
	m_nodes[n] = {pose, parent, 1};
	return n;
}

void PathTree::release(uint32_t n)
{
	while (n != NONE && --m_nodes[n].refs == 0)
	{
		m_free.push_back(n);
		n = m_nodes[n].parent;
	}
}

void PathTree::extend(size_t i, const mrpt::math::TPose2D& pose)
{
	// The particle's reference to its latest pose passes to the new node's parent link.
	m_leaf.at(i) = make(pose, m_leaf.at(i));
}

void PathTree::resample(const std::vector<size_t>& parents)
{
	std::vector<uint32_t> leaf(parents.size());
	for (size_t j = 0; j < parents.size(); j++) m_nodes[leaf[j] = m_leaf.at(parents[j])].refs++;
	for (const uint32_t n : m_leaf) release(n);
	m_leaf = std::move(leaf);
}

std::vector<mrpt::math::TPose2D> PathTree::path(size_t i) const
{
	std::vector<mrpt::math::TPose2D> out;
	for (uint32_t n = m_leaf.at(i); n != NONE; n = m_nodes[n].parent) out.push_back(m_nodes[n].pose);
	std::reverse(out.begin(), out.end());
	return out;
}
size_t PathTree::settle(const std::function<void(const mrpt::math::TPose2D&)>& sink)
{
	if (m_leaf.empty()) return 0;
	std::vector<uint32_t> chain;  // particle 0's path, latest pose first
	for (uint32_t n = m_leaf[0]; n != NONE; n = m_nodes[n].parent) chain.push_back(n);
	// From the root down: a node with one reference that is not particle 0's latest pose
	// has one child and no particle ending on it, so every path goes through that child.
	size_t k = chain.size() - 1, handed = 0;
	for (; k > 0 && m_nodes[chain[k]].refs == 1; k--, handed++)
	{
		sink(m_nodes[chain[k]].pose);
		m_free.push_back(chain[k]);
		m_nodes[chain[k - 1]].parent = NONE;
	}
	m_settled += handed;
	return handed;
}
void PathTree::mergeOlderThan(size_t i, size_t lag)
{
	const auto back = [&](uint32_t n) {
		for (size_t k = 0; k < lag && n != NONE; k++) n = m_nodes[n].parent;
		return n;
	};
	const uint32_t a = back(m_leaf.at(i));
	if (a == NONE || m_nodes[a].parent == NONE) return;  // nothing that old
	const uint32_t target = m_nodes[a].parent;
	for (const uint32_t leaf : m_leaf)
	{
		const uint32_t b = back(leaf);
		if (b == NONE || m_nodes[b].parent == NONE || m_nodes[b].parent == target) continue;
		const uint32_t old = m_nodes[b].parent;
		m_nodes[target].refs++;  // first, so that releasing the old past cannot free it
		m_nodes[b].parent = target;
		release(old);
	}
}
}  // namespace whiskermap::slam

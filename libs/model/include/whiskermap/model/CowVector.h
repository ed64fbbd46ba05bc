#pragma once
#include <array>
#include <cstddef>
#include <memory>
#include <vector>

namespace whiskermap::model
{
/** A vector whose elements live in chunks of CHUNK that copies share until one of them
 *  writes (copy-on-write, as SweptGrid's chunks): a copy costs one pointer per chunk, and a
 *  write duplicates only the chunk it lands in. Reads are const; writes go through edit(),
 *  so a read never unshares. For the lasting map's per-id arrays, which the particles of a
 *  filter copy at every resampling and each changes only near its latest sweep
 *  (doc/map-plugin.md, "Copies"). Not thread-safe: copies that share chunks must be
 *  written from one thread. */
template <class T, size_t CHUNK = 32>
class CowVector
{
   public:
	size_t size() const { return m_size; }
	bool empty() const { return m_size == 0; }
	const T& operator[](size_t i) const { return (*m_chunks[i / CHUNK])[i % CHUNK]; }
	/** Element i for writing: its chunk is duplicated first if a copy shares it. */
	T& edit(size_t i)
	{
		std::shared_ptr<Chunk>& c = m_chunks[i / CHUNK];
		if (c.use_count() > 1) c = std::make_shared<Chunk>(*c);
		return (*c)[i % CHUNK];
	}
	void push_back(const T& v)
	{
		if (m_size % CHUNK == 0) m_chunks.push_back(std::make_shared<Chunk>());
		edit(m_size++) = v;
	}
	/** Grows to n elements (the new ones `value`); never shrinks. */
	void growTo(size_t n, const T& value = T())
	{
		while (m_size < n) push_back(value);
	}
	void clear() { m_chunks.clear(), m_size = 0; }
	size_t chunkCount() const { return m_chunks.size(); }
	/** Chunks this vector shares with a copy. */
	size_t sharedChunks() const
	{
		size_t n = 0;
		for (const auto& c : m_chunks) n += c.use_count() > 1;
		return n;
	}

   private:
	using Chunk = std::array<T, CHUNK>;
	std::vector<std::shared_ptr<Chunk>> m_chunks;
	size_t m_size = 0;
};
}  // namespace whiskermap::model

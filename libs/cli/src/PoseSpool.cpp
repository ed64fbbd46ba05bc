#include <whiskermap/cli/PoseSpool.h>
#include <whiskermap/core/Error.h>

#include <cerrno>
#include <cstring>

namespace whiskermap::cli
{
PoseSpool::PoseSpool() : m_file(std::tmpfile())
{
	if (!m_file) throw core::Error(std::string("cannot create a temporary file: ") + std::strerror(errno));
}

PoseSpool::~PoseSpool() { std::fclose(m_file); }

void PoseSpool::write(double t, const mrpt::math::TPose2D& p)
{
	const double v[4] = {t, p.x, p.y, p.phi};
	if (std::fwrite(v, sizeof(v), 1, m_file) != 1)
		throw core::Error(std::string("temporary file: write failed: ") + std::strerror(errno));
	m_count++;
}

void PoseSpool::rewind()
{
	if (std::fflush(m_file) != 0 || std::fseek(m_file, 0, SEEK_SET) != 0)
		throw core::Error(std::string("temporary file: ") + std::strerror(errno));
}

bool PoseSpool::next(double& t, mrpt::math::TPose2D& p)
{
	double v[4];
	if (std::fread(v, sizeof(v), 1, m_file) != 1)
	{
		if (std::ferror(m_file)) throw core::Error("temporary file: read failed");
		return false;
	}
	t = v[0], p = {v[1], v[2], v[3]};
	return true;
}
}  // namespace whiskermap::cli

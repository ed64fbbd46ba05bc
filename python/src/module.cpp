// import whiskermap: Python bindings of the whiskermap libraries (doc/python.md).
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/core/conciseMessage.h>

#include "Bindings.h"

namespace whiskermap::python
{
py::array_t<double> posesToArray(const std::vector<mrpt::poses::CPose2D>& poses)
{
	py::array_t<double> a({static_cast<py::ssize_t>(poses.size()), py::ssize_t{3}});
	auto r = a.mutable_unchecked<2>();
	for (size_t i = 0; i < poses.size(); i++)
	{
		const auto p = fromPose2D(poses[i]);
		for (py::ssize_t k = 0; k < 3; k++) r(static_cast<py::ssize_t>(i), k) = p[static_cast<size_t>(k)];
	}
	return a;
}

std::vector<mrpt::poses::CPose2D> posesFromArray(const py::handle& obj)
{
	const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(obj);
	if (!a || a.ndim() != 2 || a.shape(1) != 3) throw core::Error("poses: expected an (n, 3) array of x, y, yaw rows");
	const auto r = a.unchecked<2>();
	std::vector<mrpt::poses::CPose2D> poses;
	for (py::ssize_t i = 0; i < r.shape(0); i++) poses.emplace_back(r(i, 0), r(i, 1), r(i, 2));
	return poses;
}

void bindErrors(py::module_& m)
{
	static py::exception<core::Error> error(m, "WhiskermapError", PyExc_ValueError);
	error.doc() =
		"Bad input (a file, a config, a value): the one-line message whiskermap's apps print after "
		"'<app>: error: ' (core::Error, and MRPT's exceptions reduced to their cause).";
	py::register_exception_translator([](std::exception_ptr p) {
		try
		{
			if (p) std::rethrow_exception(p);
		}
		catch (const py::builtin_exception&)
		{
			throw;  // pybind11's own (TypeError, IndexError, ...)
		}
		catch (const std::bad_alloc&)
		{
			throw;  // MemoryError
		}
		catch (const std::exception& e)
		{
			error(core::conciseMessage(e).c_str());
		}
	});
}
}  // namespace whiskermap::python

PYBIND11_MODULE(whiskermap, m)
{
	using namespace whiskermap::python;
	m.doc() =
		"whiskermap: object maps (tables) from whisker contacts, as MRPT classes (Fox & Prescott, "
		"TAROS 2011). Bindings of the C++ libraries: rawlogs of whisker sweeps, the map "
		"(CHierarchicalObjectMap), its sweep likelihood, the simulator and the evaluation. "
		"Units: metres and radians; poses are (x, y, yaw). See doc/python.md.";
	m.attr("__version__") = WHISKERMAP_VERSION;
	bindErrors(m);
	bindObs(m);
	bindWorld(m);
	bindMaps(m);
	bindEval(m);
}

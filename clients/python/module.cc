// gearcoupling._gearcoupling: the C++ side of `import gearcoupling` (docs/python.md). The
// package's __init__.py re-exports it with the result classes of gearcoupling/_results.py.
#include "clients/python/bindings.h"

PYBIND11_MODULE(_gearcoupling, m) {
  m.doc() = "The gearcoupling model (Guo et al., NREL) in process and through gearcoupling-service.";
  gc::python::bind_errors(m);
  gc::python::bind_couplings(m);
  gc::python::bind_calculations(m);
  gc::python::bind_case_arrays(m);
  gc::python::bind_models(m);
  gc::python::bind_recordings(m);
  gc::python::bind_measurement(m);
#ifdef GC_PYTHON_REMOTE
  gc::python::bind_client(m);
#endif
}

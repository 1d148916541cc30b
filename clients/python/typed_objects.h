// Python objects with the type help() should show: pybind11 prints a py::handle argument as
// "handle" and a py::object result as "object". Each type here is a py::object that pybind11
// accepts as is (any object; the binding checks it, as before) but names in signatures by what
// it is: `coupling: gearcoupling.Coupling | str | os.PathLike | dict`, `-> gearcoupling.
// InducedMomentsResult`, `torque_nm: numpy.ndarray | float`. test_signatures.py checks that no
// signature of the module says "handle" or "object".
#pragma once

#include <utility>

#include <pybind11/pybind11.h>

namespace gc::python {

#define GC_PYTHON_TYPED_OBJECT(Name)                                        \
  struct Name : pybind11::object {                                          \
    using pybind11::object::object;                                         \
    Name() = default;                                                       \
    Name(pybind11::object o) : pybind11::object(std::move(o)) {}            \
    static bool check_(pybind11::handle h) { return h.ptr() != nullptr; }   \
  }

// Arguments.
GC_PYTHON_TYPED_OBJECT(CouplingArgument);   ///< a Coupling, catalogue name, coupling file or dict
GC_PYTHON_TYPED_OBJECT(ModelArgument);      ///< a Model, bundled name, model file or dict
GC_PYTHON_TYPED_OBJECT(RecordingArgument);  ///< a Recording, recording file or DataFrame
GC_PYTHON_TYPED_OBJECT(ArrayArgument);      ///< a numpy array (any shape) or a number
GC_PYTHON_TYPED_OBJECT(ColumnsArgument);    ///< renames: "name=header,..." or {name: header}
GC_PYTHON_TYPED_OBJECT(NegateArgument);     ///< quantities: "torque,msy" or ["torque", "msy"]

// Results (gearcoupling/_results.py).
GC_PYTHON_TYPED_OBJECT(ToothContactResultObject);
GC_PYTHON_TYPED_OBJECT(InducedMomentsResultObject);
GC_PYTHON_TYPED_OBJECT(JamAngleResultObject);
GC_PYTHON_TYPED_OBJECT(RestoringTorqueResultObject);
GC_PYTHON_TYPED_OBJECT(FrictionEstimateResultObject);
GC_PYTHON_TYPED_OBJECT(ValidationResultObject);
GC_PYTHON_TYPED_OBJECT(DiagnosisResultObject);
GC_PYTHON_TYPED_OBJECT(CaseTableObject);

#undef GC_PYTHON_TYPED_OBJECT

}  // namespace gc::python

namespace pybind11::detail {

#define GC_PYTHON_TYPE_NAME(Name, text)                  \
  template <>                                            \
  struct handle_type_name<gc::python::Name> {            \
    static constexpr auto name = const_name(text);       \
  }

GC_PYTHON_TYPE_NAME(CouplingArgument, "gearcoupling.Coupling | str | os.PathLike | dict");
GC_PYTHON_TYPE_NAME(ModelArgument, "gearcoupling.Model | str | os.PathLike | dict");
GC_PYTHON_TYPE_NAME(RecordingArgument, "gearcoupling.Recording | str | os.PathLike | pandas.DataFrame");
GC_PYTHON_TYPE_NAME(ArrayArgument, "numpy.ndarray | float");
GC_PYTHON_TYPE_NAME(ColumnsArgument, "str | dict[str, str] | None");
GC_PYTHON_TYPE_NAME(NegateArgument, "str | list[str] | None");
GC_PYTHON_TYPE_NAME(ToothContactResultObject, "gearcoupling.ToothContactResult");
GC_PYTHON_TYPE_NAME(InducedMomentsResultObject, "gearcoupling.InducedMomentsResult");
GC_PYTHON_TYPE_NAME(JamAngleResultObject, "gearcoupling.JamAngleResult");
GC_PYTHON_TYPE_NAME(RestoringTorqueResultObject, "gearcoupling.RestoringTorqueResult");
GC_PYTHON_TYPE_NAME(FrictionEstimateResultObject, "gearcoupling.FrictionEstimateResult");
GC_PYTHON_TYPE_NAME(ValidationResultObject, "gearcoupling.ValidationResult");
GC_PYTHON_TYPE_NAME(DiagnosisResultObject, "gearcoupling.DiagnosisResult");
GC_PYTHON_TYPE_NAME(CaseTableObject, "gearcoupling.CaseTable");

#undef GC_PYTHON_TYPE_NAME

}  // namespace pybind11::detail

// gearcoupling.Model: a model configuration (a coupling and the library's effects in order) from
// a bundled name, a model file or a dict; an effect added; written out (codec/model_file.h).
#pragma once

#include <memory>
#include <string>

#include <pybind11/pybind11.h>

#include "codec/model_file.h"

namespace gc::python {

/// Immutable; copies share the file.
struct Model {
  std::shared_ptr<const codec::ModelFile> file;
};

/// A Model, a bundled model's name (codec::default_models_dir()), a model file (a str with '/'
/// or ending in ".textproto", or an os.PathLike), or a dict with the model file's fields.
/// Throws gc::InvalidInput naming the field.
Model model_argument(pybind11::handle argument);

/// This model with one more effect (or that effect replaced): a spec as validate --add takes it.
Model with_effect(const Model& model, const std::string& spec);

/// The model as a model file that reads back to the same model.
std::string model_text(const codec::ModelFile& file);

}  // namespace gc::python

#pragma once
/// \file model_file.hpp
/// Model files of cin2021's classifiers (format pathref-ml-model version 1,
/// spec/cin2021-ml.md#model-file): written by `pathref learn --save-model`, read by `pathref
/// classify --model`. The models are ml's (ml/classifier.hpp); their file format is io's
/// (docs/architecture.md#layers).
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "pathref/ml/classifier.hpp"

namespace pathref::io {

/// The model as JSON: {"format": "pathref-ml-model", "version": 1, "kind", "features",
/// "classes", "labels", "params", "model": {...}} (spec/cin2021-ml.md#model-file).
[[nodiscard]] nlohmann::json to_json(const ml::Model& m);
/// Reads a model back from a JSON value that came from no text (spec/cin2021-ml.md#model-file).
/// Every wrong format, version, type, value or shape is a ParseError `SOURCE: /pointer: expected
/// ...` (no line and column: there is no text); no library exception escapes.
[[nodiscard]] ml::Model model_from_json(const nlohmann::json& j, const std::string& source);
/// Reads a model file's text: parse errors and every refusal of model_from_json as a ParseError
/// `SOURCE:LINE:COLUMN: /pointer: expected ...` (io::parse_json_text's limits and messages).
[[nodiscard]] ml::Model parse_model(std::string_view text, const std::string& source);
/// Reads the model file `path` (io::read_input_file, at most 32 MiB) with parse_model.
[[nodiscard]] ml::Model read_model_file(const std::string& path);

}  // namespace pathref::io

// SPDX-License-Identifier: MIT
#include "io/check_input.hpp"

#include "core/bounded_read.hpp"
#include "core/errors.hpp"
#include "io/fit_file.hpp"
#include "io/model_block.hpp"

namespace admitgen::io {

checks::CheckSubject header_subject(const std::string& text, const std::string& origin) {
  return checks::subject_from_header(read_emitted_header(text, origin), text, origin);
}

checks::CheckSubject load_check_subject(const std::string& path, const std::string& order, Estimate estimate) {
  const std::string text = read_bounded(path, kMaxDocumentBytes, "fit.json or header");
  if (is_json(text)) return checks::subject_from_fit(parse_fit(text, path), path, order, estimate);
  if (text.find("admitgen:model") == std::string::npos)
    throw FileError(path, 0, "neither a fit.json nor a header written by admitgen emit (no admitgen:model block)");
  return header_subject(text, path);
}

}  // namespace admitgen::io

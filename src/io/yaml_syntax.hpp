#pragma once
// A YAML syntax error of a deck as a message with its cause and fix. yaml-cpp names the problem
// where it noticed it, often lines after the cause and in its own terms; the message names the
// cause where the text shows it: a tab in the indentation, a bracket left open (and where it was
// opened), a closing bracket that closes nothing or closes the wrong bracket (and what may close
// there), a `: ` inside a value without quotes (and the value quoted).
#include <yaml-cpp/yaml.h>

#include <string>

#include "core/errors.hpp"

namespace tunica {

/// The InputError for `e`, which yaml-cpp threw reading the deck `text` of `file`.
InputError yaml_syntax_error(const YAML::Exception& e, const std::string& text, const std::string& file);

}  // namespace tunica

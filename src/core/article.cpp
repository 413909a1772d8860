#include "core/article.hpp"

#include <cctype>

namespace tunica {

std::string with_article(std::string_view noun) {
  const auto starts = [&](std::string_view p) { return noun.substr(0, p.size()) == p; };
  const char c = noun.empty() ? 'x' : static_cast<char>(std::tolower(static_cast<unsigned char>(noun.front())));
  const bool vowel = (c == 'a' || c == 'e' || c == 'i' || c == 'o' || c == 'u') && !starts("uni") && !starts("use") &&
                     !starts("usu") && !starts("one");
  return std::string(vowel ? "an " : "a ").append(noun);
}

}  // namespace tunica

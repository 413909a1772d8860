#pragma once
// The indefinite article of a noun that a message builds from parts ("a length", "an angle").
#include <string>
#include <string_view>

namespace tunica {

/// `noun` after "a" or "an", by its first letter: "an" before a vowel, "a" otherwise and before
/// the vowels read as a consonant ("a unit", "a user", "a one-sided ...").
std::string with_article(std::string_view noun);

}  // namespace tunica

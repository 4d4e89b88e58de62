/// @file markup.hpp  Text for markup languages: XML (SVG, HTML).
#pragma once
#include <string>

namespace kinergy {

/// `s` as XML character data or an attribute value: < > & " escaped.
std::string xml_escape(const std::string& s);

}  // namespace kinergy

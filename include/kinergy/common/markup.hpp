/// @file markup.hpp  Text for markup languages and data formats: XML (SVG, HTML), JSON.
#pragma once
#include <string>

namespace kinergy {

/// `s` as XML character data or an attribute value: < > & " escaped.
std::string xml_escape(const std::string& s);

/// `s` as a JSON string, quotes included (" \ and control characters escaped).
std::string json_quote(const std::string& s);

}  // namespace kinergy

// SPDX-License-Identifier: MIT
// Probe for tools/check-doc-sections: five citations resolve, two do not.
// (docs/page.md, "Real section") and (docs/page.md "A bold title") and (docs/page.md, "first part")
// (docs/page.md, "Real section (with a note)", and "No such
// section")
std::string s = "see (docs/page.md " + std::string(", not a citation, ") + ")";
// (docs/missing.md, "Anything") (docs/page.md, "Page")

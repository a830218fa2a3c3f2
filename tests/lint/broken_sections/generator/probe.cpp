// SPDX-License-Identifier: MIT
// Probe for tools/check-doc-sections: eight citations resolve, five do not.
// (docs/page.md, "Real section") and (docs/page.md "A bold title") and (docs/page.md, "first part")
// (docs/page.md, "Real section (with a note)", and "No such
// section")
std::string s = "see (docs/page.md " + std::string(", not a citation, ") + ")";
// (docs/missing.md, "Anything") (docs/page.md, "Page")
// docs/page.md §2.1 and docs/page.md §2. and Docs/page.md ("A bold title": the parenthesised form)
// docs/page.md §3 and docs/page.md §2.2; Docs/page.md ("No such heading")

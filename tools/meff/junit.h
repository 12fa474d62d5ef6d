// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// JUnit XML, which every CI shows natively (GitLab's test report, GitHub Actions' test
// reporters, Jenkins): one <testsuite> per file inside <testsuites>, one <testcase> per item.
// The <testsuite> element and its end tag stand on lines of their own, so the files of several
// shards merge into one by taking their <testsuite> blocks into one <testsuites>
// (docs/validation.md: "Regression runs").
#pragma once

#include <string>
#include <vector>

namespace meff::cli
{

struct JUnitCase
{
    enum class Outcome
    {
        Passed,
        Failed,  ///< <failure>: the check ran and did not hold
        Error,   ///< <error>: the check could not run to its end
        Skipped, ///< <skipped>: the check does not apply (the message says why)
    };

    std::string name;      ///< testcase name
    std::string className; ///< testcase classname (CIs group by it)
    std::string file;      ///< the input file, as the "file" attribute
    double seconds = 0;    ///< wall time
    Outcome outcome = Outcome::Passed;
    std::string message; ///< one line: the failure's, error's or skip's "message"
    std::string type;    ///< the failure's or error's "type"
    std::string text;    ///< the body of <failure>/<error>: the details, several lines
    std::string output;  ///< <system-out>: what the run printed about the case (may be empty)
};

/// The XML text of one test suite in a <testsuites> document. The suite's <properties> hold
/// meff's version ("meff.version").
std::string JUnitDocument(const std::string& suiteName, const std::vector<JUnitCase>& cases,
                          double seconds);

/// `text` safe inside XML attribute values and text: & < > " ' escaped, and characters XML 1.0
/// forbids (control characters other than tab, newline and carriage return) replaced by '?'.
std::string XmlEscape(const std::string& text);

} // namespace meff::cli

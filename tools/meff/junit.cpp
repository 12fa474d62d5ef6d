// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
#include "junit.h"

#include "meff_version.h"

#include <cstdio>

namespace meff::cli
{

namespace
{

std::string Seconds(double seconds)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", seconds);
    return text;
}

std::string Attribute(const char* name, const std::string& value)
{
    return std::string(" ") + name + "=\"" + XmlEscape(value) + "\"";
}

} // namespace

std::string XmlEscape(const std::string& text)
{
    std::string escaped;
    escaped.reserve(text.size());
    for (const char c : text)
    {
        switch (c)
        {
        case '&':
            escaped += "&amp;";
            break;
        case '<':
            escaped += "&lt;";
            break;
        case '>':
            escaped += "&gt;";
            break;
        case '"':
            escaped += "&quot;";
            break;
        case '\'':
            escaped += "&apos;";
            break;
        default:
        {
            const auto byte = static_cast<unsigned char>(c);
            escaped += (byte < 0x20 && c != '\t' && c != '\n' && c != '\r') ? '?' : c;
        }
        }
    }
    return escaped;
}

std::string JUnitDocument(const std::string& suiteName, const std::vector<JUnitCase>& cases,
                          double seconds)
{
    int failures = 0;
    int errors = 0;
    int skipped = 0;
    for (const JUnitCase& testCase : cases)
    {
        failures += testCase.outcome == JUnitCase::Outcome::Failed ? 1 : 0;
        errors += testCase.outcome == JUnitCase::Outcome::Error ? 1 : 0;
        skipped += testCase.outcome == JUnitCase::Outcome::Skipped ? 1 : 0;
    }
    std::string xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites>\n";
    xml += "<testsuite" + Attribute("name", suiteName) +
           Attribute("tests", std::to_string(cases.size())) +
           Attribute("failures", std::to_string(failures)) +
           Attribute("errors", std::to_string(errors)) +
           Attribute("skipped", std::to_string(skipped)) + Attribute("time", Seconds(seconds)) +
           ">\n";
    xml += "  <properties><property" + Attribute("name", "meff.version") +
           Attribute("value", MEFF_VERSION) + "/></properties>\n";
    for (const JUnitCase& testCase : cases)
    {
        xml += "  <testcase" + Attribute("classname", testCase.className) +
               Attribute("name", testCase.name) + Attribute("file", testCase.file) +
               Attribute("time", Seconds(testCase.seconds));
        if (testCase.outcome == JUnitCase::Outcome::Passed && testCase.output.empty())
        {
            xml += "/>\n";
            continue;
        }
        xml += ">\n";
        if (testCase.outcome == JUnitCase::Outcome::Skipped)
        {
            xml += "    <skipped" + Attribute("message", testCase.message) + "/>\n";
        }
        else if (testCase.outcome != JUnitCase::Outcome::Passed)
        {
            const char* element =
                testCase.outcome == JUnitCase::Outcome::Failed ? "failure" : "error";
            xml += std::string("    <") + element + Attribute("message", testCase.message) +
                   Attribute("type", testCase.type) + ">" + XmlEscape(testCase.text) + "</" +
                   element + ">\n";
        }
        if (!testCase.output.empty())
        {
            xml += "    <system-out>" + XmlEscape(testCase.output) + "</system-out>\n";
        }
        xml += "  </testcase>\n";
    }
    xml += "</testsuite>\n</testsuites>\n";
    return xml;
}

} // namespace meff::cli

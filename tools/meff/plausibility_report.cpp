// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
#include "plausibility_report.h"

#include <cstdio>

namespace meff::cli
{

namespace
{

std::string Short(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    return text;
}

} // namespace

std::string PlausibilityText(const validation::PlausibilityResult& result)
{
    std::string line = std::string(result.passed ? "PASS" : "FAIL") + " plausibility " +
                       result.scene + " (solver " + result.solver + ", " +
                       std::to_string(result.frames) + " frames):";
    std::string failures;
    bool first = true;
    for (const validation::PlausibilityCheck& check : result.checks)
    {
        if (!check.applies)
        {
            continue;
        }
        line += std::string(first ? " " : ", ") + check.name + " " + Short(check.value) +
                (check.unit[0] != '\0' ? std::string(" ") + check.unit : "") + " (limit " +
                Short(check.limit) + ")";
        first = false;
        if (!check.passed)
        {
            failures += "  " + validation::DescribeCheck(check) + "\n";
        }
    }
    return line + "\n" + failures;
}

nlohmann::json PlausibilityJson(const validation::PlausibilityResult& result)
{
    nlohmann::json checks = nlohmann::json::object();
    for (const validation::PlausibilityCheck& check : result.checks)
    {
        checks[check.name] = {
            {"applies", check.applies},
            {"passed", check.passed},
            {"value", check.value},
            {"limit", check.limit},
            {"unit", check.unit},
            {"frame", check.frame >= 0 ? nlohmann::json(check.frame) : nlohmann::json()},
            {"where", check.where},
            {"note", check.note}};
    }
    return {{"solver", result.solver},
            {"frames", result.frames},
            {"passed", result.passed},
            {"checks", checks}};
}

void AddPlausibilityToCase(const validation::PlausibilityResult& result, JUnitCase& testCase)
{
    testCase.output += PlausibilityText(result);
    if (result.passed)
    {
        return;
    }
    std::string failed;
    for (const validation::PlausibilityCheck& check : result.checks)
    {
        const std::string text = validation::DescribeCheck(check);
        if (!text.empty())
        {
            failed += (failed.empty() ? "" : ", ") + check.name;
            testCase.text += text + "\n";
        }
    }
    if (testCase.outcome == JUnitCase::Outcome::Passed)
    {
        testCase.outcome = JUnitCase::Outcome::Failed;
        testCase.type = "plausibility";
        testCase.message = "implausible under " + result.solver + ": " + failed;
    }
}

} // namespace meff::cli

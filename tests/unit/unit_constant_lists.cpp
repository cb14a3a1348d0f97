// SPDX-License-Identifier: BSD-3-Clause
// The lists of constants agree wherever they are written down: the public header
// (include/surfadapt.h) is the source; the Fortran module must declare every SFA_*
// constant with the same name and value, the library's range table
// (src/adapt/parameters.cpp) must hold the keys of enum sfa_param in the same order with
// the unit, range and default the header documents, sfa_set_param and sfa_get_param_bounds
// must accept exactly the documented range, and sfa_measure must accept exactly the
// quantities of enum sfa_measure_quantity. The sources are read from the top of the tree,
// where the tests run.
#include "adapt/parameters.hpp"

#include "surfadapt.h"

#include <cctype>
#include <cmath>
#include <cstdarg>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <regex>
#include <setjmp.h>
#include <sstream>
#include <string>
#include <vector>

extern "C" {
#include <cmocka.h>

#include "support/shapes.h"
}

using namespace sfa;

namespace {

const char *const header_path = "include/surfadapt.h";
const char *const fortran_path = "bindings/fortran/surfadapt.f90";
const char *const param_enum_path = "src/adapt/parameters.hpp";

// Fortran names are case-insensitive, so the header's SFA_ABI_VERSION would clash with the
// function sfa_abi_version: the module renames it (README, "Using it from Fortran").
const std::map<std::string, std::string> fortran_renames = {{"SFA_ABI_VERSION", "SFA_HEADER_ABI_VERSION"}};

// Every disagreement found by one test, reported together before the test fails.
class Findings {
public:
    void add(const char *format, ...) __attribute__((format(printf, 2, 3)))
    {
        char text[512];
        va_list args;
        va_start(args, format);
        std::vsnprintf(text, sizeof text, format, args);
        va_end(args);
        lines_.push_back(text);
    }
    void report() const
    {
        for (const std::string &line : lines_)
            print_error("%s\n", line.c_str());
        if (!lines_.empty())
            fail_msg("%zu disagreement(s), listed above", lines_.size());
    }

private:
    std::vector<std::string> lines_;
};

std::string read_source(const char *path)
{
    std::ifstream in(path);
    if (!in)
        fail_msg("cannot read %s: run the test from the top of the source tree, as make test does", path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::string upper(std::string s)
{
    for (char &c : s)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

std::string trim(const std::string &s)
{
    const size_t first = s.find_first_not_of(" \t\r\n");
    if (first == std::string::npos)
        return "";
    return s.substr(first, s.find_last_not_of(" \t\r\n") - first + 1);
}

// A whole decimal number, all of `text`.
bool parse_integer(const std::string &text, long *value)
{
    const std::string t = trim(text);
    if (t.empty())
        return false;
    char *end = nullptr;
    *value = std::strtol(t.c_str(), &end, 10);
    return *end == '\0';
}

struct Constant {
    std::string name;
    long value;
    std::string doc; // the enumerator's Doxygen text, whitespace collapsed
};

// The text of a Doxygen comment without its delimiters, leading stars and line breaks.
std::string doc_text(const std::string &comment)
{
    std::string body = comment.substr(3, comment.size() - 5); // without "/**" and "*/"
    if (!body.empty() && body[0] == '<')
        body.erase(0, 1);
    std::istringstream lines(body);
    std::string line, text;
    while (std::getline(lines, line)) {
        line = trim(line);
        if (!line.empty() && line[0] == '*')
            line = trim(line.substr(1));
        if (!line.empty())
            text += (text.empty() ? "" : " ") + line;
    }
    return text;
}

// The enumerators of `enum <name> { ... };` in the header, each with the "/** */" comment
// before it or the "/**< */" comment after it. Every enumerator must have an explicit value:
// the values are the binary interface, and a written value is one a reviewer sees change.
std::vector<Constant> header_enum(const std::string &header, const std::string &name)
{
    const std::string opening = "enum " + name + " {";
    const size_t start = header.find(opening);
    if (start == std::string::npos)
        fail_msg("%s has no \"%s\"", header_path, opening.c_str());
    const size_t end = header.find("};", start);
    const std::string body = header.substr(start + opening.size(), end - start - opening.size());

    std::vector<Constant> constants;
    std::string pending_doc;
    size_t i = 0;
    while (i < body.size()) {
        if (std::isspace(static_cast<unsigned char>(body[i])) || body[i] == ',') {
            ++i;
        } else if (body.compare(i, 2, "/*") == 0) {
            const size_t close = body.find("*/", i + 2);
            if (close == std::string::npos)
                fail_msg("%s: unterminated comment in enum %s", header_path, name.c_str());
            const std::string comment = body.substr(i, close + 2 - i);
            if (comment.compare(0, 4, "/**<") == 0 && !constants.empty())
                constants.back().doc = doc_text(comment);
            else if (comment.compare(0, 3, "/**") == 0)
                pending_doc = doc_text(comment);
            i = close + 2;
        } else {
            const size_t stop = body.find_first_of(",/", i);
            const std::string item = body.substr(i, stop == std::string::npos ? std::string::npos : stop - i);
            const size_t equals = item.find('=');
            Constant c{trim(item.substr(0, equals)), 0, pending_doc};
            if (equals == std::string::npos || !parse_integer(item.substr(equals + 1), &c.value))
                fail_msg("%s: enum %s: \"%s\" has no explicit whole-number value", header_path, name.c_str(),
                         trim(item).c_str());
            constants.push_back(c);
            pending_doc.clear();
            i = stop == std::string::npos ? body.size() : stop;
        }
    }
    if (constants.empty())
        fail_msg("%s: enum %s is empty", header_path, name.c_str());
    return constants;
}

// Every integer SFA_* macro and the enumerators of every enum sfa_*.
std::vector<Constant> header_constants(const std::string &header)
{
    std::vector<Constant> constants;
    std::istringstream lines(header);
    std::string line;
    const std::regex define(R"(^#define\s+(SFA_[A-Z0-9_]+)\s+(-?[0-9]+)\s*$)");
    const std::regex enum_opening(R"(^enum\s+(sfa_[a-z0-9_]+)\s*\{)");
    std::smatch m;
    while (std::getline(lines, line)) {
        if (std::regex_match(line, m, define))
            constants.push_back({m[1], std::strtol(m[2].str().c_str(), nullptr, 10), ""});
        else if (std::regex_search(line, m, enum_opening))
            for (const Constant &c : header_enum(header, m[1]))
                constants.push_back(c);
    }
    return constants;
}

// The named integer constants of the Fortran module whose names start with SFA_, in
// upper case (Fortran ignores case), with their values.
std::map<std::string, long> fortran_constants(const std::string &module, Findings &findings)
{
    std::map<std::string, long> constants;
    std::istringstream lines(module);
    std::string line;
    int number = 0;
    const std::regex declaration(R"(^\s*integer\b.*\bparameter\b.*::\s*(\w+)\s*=\s*([^!]*))", std::regex::icase);
    std::smatch m;
    while (std::getline(lines, line)) {
        ++number;
        if (!std::regex_search(line, m, declaration))
            continue;
        const std::string name = upper(m[1]);
        if (name.compare(0, 4, "SFA_") != 0)
            continue;
        long value = 0;
        if (!parse_integer(m[2], &value)) {
            findings.add("%s:%d: %s = %s is not a whole-number literal", fortran_path, number, name.c_str(),
                         trim(m[2]).c_str());
            continue;
        }
        if (constants.count(name))
            findings.add("%s:%d: %s is declared twice", fortran_path, number, name.c_str());
        constants[name] = value;
    }
    return constants;
}

// The enumerators of `enum class Param` in src/adapt/parameters.hpp, in order, without `count`.
std::vector<std::string> param_enum_names()
{
    const std::string text = read_source(param_enum_path);
    const std::string opening = "enum class Param : int {";
    const size_t start = text.find(opening);
    if (start == std::string::npos)
        fail_msg("%s has no \"%s\"", param_enum_path, opening.c_str());
    const size_t end = text.find("};", start);
    std::istringstream items(text.substr(start + opening.size(), end - start - opening.size()));
    std::vector<std::string> names;
    std::string item;
    while (std::getline(items, item, ',')) {
        item = trim(item.substr(0, item.find('=')));
        if (!item.empty())
            names.push_back(item);
    }
    if (names.empty() || names.back() != "count")
        fail_msg("%s: enum class Param must end with count", param_enum_path);
    names.pop_back();
    return names;
}

// The values must be 0, 1, ..., n-1 in the header's order, so that a range check
// "0 <= value < n" accepts exactly the listed constants.
void require_numbered_in_order(const std::vector<Constant> &list, const char *what, Findings &findings)
{
    for (size_t i = 0; i < list.size(); ++i)
        if (list[i].value != static_cast<long>(i))
            findings.add("%s: %s is %ld but is listed as number %zu of enum %s (values must run 0, 1, 2, ...)",
                         header_path, list[i].name.c_str(), list[i].value, i, what);
}

// ------------------------------------------------------------------ the Fortran module

void fortran_module_declares_every_header_constant(void **)
{
    const std::vector<Constant> header = header_constants(read_source(header_path));
    Findings findings;
    std::map<std::string, long> fortran = fortran_constants(read_source(fortran_path), findings);
    for (const Constant &c : header) {
        const auto renamed = fortran_renames.find(c.name);
        const std::string name = renamed == fortran_renames.end() ? c.name : renamed->second;
        const auto f = fortran.find(name);
        if (f == fortran.end())
            findings.add("%s is %ld in %s but missing from %s", name.c_str(), c.value, header_path, fortran_path);
        else if (f->second != c.value)
            findings.add("%s is %ld in %s but %ld in %s", name.c_str(), c.value, header_path, f->second,
                         fortran_path);
        if (f != fortran.end())
            fortran.erase(f);
    }
    for (const auto &[name, value] : fortran)
        findings.add("%s (%ld) is in %s but not in %s", name.c_str(), value, fortran_path, header_path);
    findings.report();
    // Not vacuous: the three enums and the version macros were read.
    assert_true(header.size() > 40);
}

// ------------------------------------------------------------------ enum sfa_param

std::vector<Constant> header_params()
{
    return header_enum(read_source(header_path), "sfa_param");
}

void param_keys_are_the_range_table_in_order(void **)
{
    const std::vector<Constant> keys = header_params();
    const std::vector<std::string> enum_names = param_enum_names();
    Findings findings;
    require_numbered_in_order(keys, "sfa_param", findings);
    if (keys.size() != static_cast<size_t>(Param::count))
        findings.add("%s lists %zu keys in enum sfa_param, src/adapt/parameters.cpp has %d specs", header_path,
                     keys.size(), static_cast<int>(Param::count));
    if (enum_names.size() != static_cast<size_t>(Param::count))
        findings.add("%s: enum class Param has %zu keys before count, the range table %d", param_enum_path,
                     enum_names.size(), static_cast<int>(Param::count));
    for (const Constant &key : keys) {
        if (!Parameters::is_key(static_cast<int>(key.value))) {
            findings.add("%s = %ld: the library does not know this key", key.name.c_str(), key.value);
            continue;
        }
        const ParamSpec &spec = Parameters::spec(static_cast<int>(key.value));
        if (key.name != spec.name)
            findings.add("key %ld is %s in %s but %s in src/adapt/parameters.cpp", key.value, key.name.c_str(),
                         header_path, spec.name);
        const std::string expected = [&] {
            std::string lower = key.name.substr(std::string("SFA_PARAM_").size());
            for (char &ch : lower)
                ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
            return lower;
        }();
        if (static_cast<size_t>(key.value) < enum_names.size() && enum_names[key.value] != expected)
            findings.add("key %ld is %s in %s, so Param::%s is expected at that place in %s, found Param::%s",
                         key.value, key.name.c_str(), header_path, expected.c_str(), param_enum_path,
                         enum_names[key.value].c_str());
    }
    // The C tests size their tables of keys by SHAPES_NPARAMS (tests/c/support/shapes.h).
    if (keys.size() != SHAPES_NPARAMS)
        findings.add("SHAPES_NPARAMS is %d in tests/c/support/shapes.h, but enum sfa_param has %zu keys",
                     SHAPES_NPARAMS, keys.size());
    findings.report();
}

// "Unit, range; default value." at the end of a key's documentation.
struct Documented {
    std::string unit, range, default_text;
};

bool documented(const Constant &key, Documented *out)
{
    static const std::regex last_sentence(
        R"(([A-Z][A-Za-z ]*), (>= \S+|> \S+|in [\[(][^\])]*[\])]|0 or 1|a whole number in \[[^\]]*\]); )"
        R"(default ((?:[^;.]|\.[0-9])*)\.$)");
    std::smatch m;
    if (!std::regex_search(key.doc, m, last_sentence))
        return false;
    out->unit = m[1];
    out->unit[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(out->unit[0])));
    out->range = m[2];
    out->default_text = m[3];
    return true;
}

double default_of(int key)
{
    sfa_surface *s = nullptr;
    assert_int_equal(sfa_create(&s), SFA_OK);
    double value = NAN;
    assert_int_equal(sfa_get_param(s, key, &value), SFA_OK);
    sfa_destroy(s);
    return value;
}

// Whether the documented default (a number, or "expression = rounded number") is `value`:
// exactly, or to the digits written after an "=".
bool default_agrees(const std::string &text, double value)
{
    const size_t equals = text.rfind('=');
    const std::string number = trim(equals == std::string::npos ? text : text.substr(equals + 1));
    char *end = nullptr;
    const double written = std::strtod(number.c_str(), &end);
    if (end == number.c_str() || *end != '\0')
        return false;
    if (equals == std::string::npos)
        return written == value;
    const size_t point = number.find('.');
    const int decimals = point == std::string::npos ? 0 : static_cast<int>(number.size() - point - 1);
    return std::fabs(written - value) <= 0.5 * std::pow(10.0, -decimals);
}

void param_docs_state_the_tables_unit_range_and_default(void **)
{
    Findings findings;
    for (const Constant &key : header_params()) {
        Documented doc;
        if (!documented(key, &doc)) {
            findings.add("%s: its documentation in %s must end with \"Unit, range; default value.\", "
                         "e.g. \"Degrees, in (0, 180); default 45.\"",
                         key.name.c_str(), header_path);
            continue;
        }
        if (!Parameters::is_key(static_cast<int>(key.value)))
            continue; // reported by param_keys_are_the_range_table_in_order
        const ParamSpec &spec = Parameters::spec(static_cast<int>(key.value));
        if (doc.unit != spec.unit)
            findings.add("%s: the header gives the unit \"%s\", the range table \"%s\"", key.name.c_str(),
                         doc.unit.c_str(), spec.unit);
        const std::string range = Parameters::describe_range(spec);
        if (doc.range != range)
            findings.add("%s: the header documents the range \"%s\", the range table checks \"%s\"",
                         key.name.c_str(), doc.range.c_str(), range.c_str());
        const double actual = default_of(static_cast<int>(key.value));
        if (!default_agrees(doc.default_text, actual))
            findings.add("%s: the header documents the default \"%s\", the library's is %.17g", key.name.c_str(),
                         doc.default_text.c_str(), actual);
    }
    findings.report();
}

// A range as the header writes it, read without the library's help.
struct Range {
    double lowest, highest;
    bool lowest_accepted, highest_accepted, whole_numbers_only;
};

bool read_range(const std::string &text, Range *r)
{
    const std::string number = R"((-?[0-9]+(?:\.[0-9]+)?(?:e[-+]?[0-9]+)?))";
    std::smatch m;
    const auto number_at = [&](int i) { return std::strtod(m[i].str().c_str(), nullptr); };
    if (std::regex_match(text, m, std::regex(">= " + number)))
        *r = {number_at(1), INFINITY, true, false, false};
    else if (std::regex_match(text, m, std::regex("> " + number)))
        *r = {number_at(1), INFINITY, false, false, false};
    else if (std::regex_match(text, m, std::regex(R"(in ([\[(]))" + number + ", " + number + R"(([\])]))")))
        *r = {number_at(2), number_at(3), m[1] == "[", m[4] == "]", false};
    else if (text == "0 or 1")
        *r = {0, 1, true, true, true};
    else if (std::regex_match(text, m, std::regex(R"(a whole number in \[)" + number + ", " + number + R"(\])")))
        *r = {number_at(1), number_at(2), true, true, true};
    else
        return false;
    return true;
}

void set_param_and_bounds_follow_the_documented_range(void **)
{
    sfa_surface *s = nullptr;
    assert_int_equal(sfa_create(&s), SFA_OK);
    Findings findings;
    int probes = 0;
    for (const Constant &key : header_params()) {
        Documented doc;
        Range r{};
        if (!documented(key, &doc)) {
            findings.add("%s: no \"Unit, range; default value.\" at the end of its documentation", key.name.c_str());
            continue;
        }
        if (!read_range(doc.range, &r)) {
            findings.add("%s: the range \"%s\" is in no form this test reads (\">= a\", \"> a\", \"in (a, b]\", \"0 or 1\", "
                         "\"a whole number in [a, b]\")",
                         key.name.c_str(), doc.range.c_str());
            continue;
        }
        const int k = static_cast<int>(key.value);
        const auto expect = [&](double value, bool accepted, const char *why) {
            ++probes;
            const int rc = sfa_set_param(s, k, value);
            if ((rc == SFA_OK) != accepted)
                findings.add("%s = %.17g (%s): sfa_set_param gives %s, but the header documents %s",
                             key.name.c_str(), value, why, sfa_status_string(rc), doc.range.c_str());
        };
        expect(NAN, false, "not a number");
        expect(-INFINITY, false, "minus infinity");
        expect(INFINITY, false, "infinity");
        expect(r.lowest, r.lowest_accepted, "the lower end");
        expect(std::nextafter(r.lowest, -INFINITY), false, "just below the lower end");
        if (r.whole_numbers_only)
            expect(r.lowest + 0.5, false, "a fraction above the lower end");
        else
            expect(std::nextafter(r.lowest, INFINITY), true, "just above the lower end");
        if (std::isfinite(r.highest)) {
            expect(r.highest, r.highest_accepted, "the upper end");
            expect(std::nextafter(r.highest, INFINITY), false, "just above the upper end");
            if (r.whole_numbers_only)
                expect(r.highest - 0.5, false, "a fraction below the upper end");
            else
                expect(std::nextafter(r.highest, -INFINITY), true, "just below the upper end");
        } else {
            expect(1e300, true, "far above the lower end, where there is no upper end");
        }

        double lowest = NAN, highest = NAN;
        const int rc = sfa_get_param_bounds(k, &lowest, &highest);
        if (rc != SFA_OK || lowest != r.lowest || highest != r.highest)
            findings.add("%s: sfa_get_param_bounds gives %s, [%.17g, %.17g]; the header documents %s",
                         key.name.c_str(), sfa_status_string(rc), lowest, highest, doc.range.c_str());
    }
    sfa_destroy(s);
    findings.report();
    assert_true(probes > 100);
}

// ------------------------------------------------------------------ enum sfa_measure_quantity

void measure_accepts_exactly_the_listed_quantities(void **)
{
    const std::vector<Constant> quantities = header_enum(read_source(header_path), "sfa_measure_quantity");
    Findings findings;
    require_numbered_in_order(quantities, "sfa_measure_quantity", findings);
    sfa_mesh_data cube = shape_unit_cube();
    sfa_surface *s = surface_from(&cube, 0, nullptr, 0);
    mesh_free(&cube);
    assert_non_null(s);
    double value = 0;
    for (const Constant &q : quantities) {
        const int rc = sfa_measure(s, static_cast<int>(q.value), &value);
        if (rc != SFA_OK)
            findings.add("sfa_measure(%s = %ld) on a cube gives %s: %s", q.name.c_str(), q.value,
                         sfa_status_string(rc), sfa_last_error(s));
    }
    const long unlisted[] = {-1, static_cast<long>(quantities.size())};
    for (const long q : unlisted) {
        const int rc = sfa_measure(s, static_cast<int>(q), &value);
        if (rc != SFA_ERR_ARGUMENT || !std::strstr(sfa_last_error(s), "unknown quantity"))
            findings.add("sfa_measure(%ld), which enum sfa_measure_quantity does not list, gives %s (\"%s\"), "
                         "expected SFA_ERR_ARGUMENT for an unknown quantity",
                         q, sfa_status_string(rc), sfa_last_error(s));
    }
    sfa_destroy(s);
    findings.report();
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(fortran_module_declares_every_header_constant),
        cmocka_unit_test(param_keys_are_the_range_table_in_order),
        cmocka_unit_test(param_docs_state_the_tables_unit_range_and_default),
        cmocka_unit_test(set_param_and_bounds_follow_the_documented_range),
        cmocka_unit_test(measure_accepts_exactly_the_listed_quantities),
    };
    return cmocka_run_group_tests_name("unit_constant_lists", tests, nullptr, nullptr);
}

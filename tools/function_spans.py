"""The functions of a source file as (name, first line, last line), for
tools/check_structure.py's limit on a function's length.

C++ and GLSL are read by matching braces over the code with its comments,
string and character literals and preprocessor lines blanked: a function is
a brace block at namespace or class scope whose header has a parameter list,
and spans from its header's first line to its closing brace; lambdas and
blocks inside it are part of it. Python is read by its own parser, and its
functions are those at module or class level.
"""

import ast
import re

# extern "C" { ... } (its string blanked) holds declarations; extern "C" int f(...) { is a function.
SCOPE_HEADER = re.compile(r"^(?:(?:template\s*<.*>\s*)?(?:inline\s+)?(?:namespace|class|struct|union)\b"
                          r"|extern\s*$)", re.S)
ACCESS_LABEL = re.compile(r"\b(?:public|private|protected)\s*$")
# operator=, operator== and the like have an '=' that assigns nothing.
OPERATOR_NAME = re.compile(r"\boperator\s*[^\s(]*")
# What may follow a function's parameter list: qualifiers, a trailing return
# type, a constructor's initializer list.
AFTER_PARAMETERS = re.compile(r"^(?:\s|const\b|override\b|final\b|mutable\b|volatile\b|noexcept\b(?:\(.*\))?|&)*"
                              r"(?:(?:->|:(?!:)).*)?$", re.S)
LAST_NAME = re.compile(r"([~\w:]+(?:\s*<[^(]*>)?)\s*$")


def blank_comments_and_literals(text):
    """text with comments, string and character literals and preprocessor
    directives replaced by spaces, newlines kept, so braces in them are not code."""
    out = list(text)
    i, n = 0, len(text)
    line_start = True

    def blank(start, end):
        for k in range(start, min(end, n)):
            if out[k] != "\n":
                out[k] = " "

    while i < n:
        c = text[i]
        if c == "\n":
            line_start = True
            i += 1
            continue
        if line_start and c == "#":
            end = i
            while end < n and (text[end] != "\n" or text[end - 1] == "\\"):
                end += 1
            blank(i, end)
            i = end
            continue
        if not c.isspace():
            line_start = False
        if text.startswith("//", i):
            end = text.find("\n", i)
            end = n if end < 0 else end
        elif text.startswith("/*", i):
            end = text.find("*/", i + 2)
            end = n if end < 0 else end + 2
        elif c == '"' and i > 0 and text[i - 1] == "R":
            delimiter = text[i + 1 : text.find("(", i)]
            end = text.find(")" + delimiter + '"', i)
            end = n if end < 0 else end + len(delimiter) + 2
        elif c == '"' or (c == "'" and not (i > 0 and text[i - 1].isalnum())):  # 1'000 separates digits
            end = i + 1
            while end < n and text[end] != c and text[end] != "\n":
                end += 2 if text[end] == "\\" else 1
            end += 1
        else:
            i += 1
            continue
        blank(i, end)
        i = end
    return "".join(out)


def matching_brace(code, opening):
    depth = 0
    for k in range(opening, len(code)):
        if code[k] == "{":
            depth += 1
        elif code[k] == "}":
            depth -= 1
            if depth == 0:
                return k
    return len(code) - 1


def parameter_list_end(header):
    """The index just after the ')' closing header's first '(', or -1."""
    depth = 0
    for k in range(max(header.find("("), 0), len(header)):
        depth += {"(": 1, ")": -1}.get(header[k], 0)
        if header[k] == ")" and depth == 0:
            return k + 1
    return -1


def is_function_header(header):
    header = OPERATOR_NAME.sub("operator", header)
    first_paren = header.find("(")
    end = parameter_list_end(header)
    return (first_paren >= 0 and end >= 0 and "=" not in header[:first_paren]
            and not header.lstrip().startswith("enum") and AFTER_PARAMETERS.match(header[end:]))


def is_member_initializer(header):
    """Whether a '{' after header opens a member's {} in a constructor's
    initializer list (Type::Type(...) : member{...}) rather than the body."""
    rest = header[parameter_list_end(header):]
    return re.search(r"(?<!:):(?!:)", rest) is not None and re.search(r"[\w>]\s*$", rest) is not None


def brace_functions(text):
    """(name, first line, last line) of each function in C++ or GLSL text."""
    code = blank_comments_and_literals(text)
    functions = []
    header_start, paren_depth, i = 0, 0, 0
    while i < len(code):
        c = code[i]
        if c in "([":
            paren_depth += 1
        elif c in ")]":
            paren_depth -= 1
        elif c in ";}" or (c == ":" and ACCESS_LABEL.search(code[header_start:i])):
            header_start, paren_depth = i + 1, 0
        elif c == "{":
            header = code[header_start:i]
            if paren_depth == 0 and SCOPE_HEADER.match(header.strip()):
                header_start = i + 1  # its members are read at this same level
            elif paren_depth != 0 or not is_function_header(header) or is_member_initializer(header):
                # A default argument, an initializer, an enum, or a member's
                # {} in a constructor's initializer list: not a body.
                i = matching_brace(code, i)
            else:
                close = matching_brace(code, i)
                first = header_start + len(header) - len(header.lstrip())
                name = LAST_NAME.search(header[: header.find("(")])
                functions.append((name.group(1) if name else "?", code.count("\n", 0, first) + 1,
                                  code.count("\n", 0, close) + 1))
                i, header_start, paren_depth = close, close + 1, 0
        i += 1
    return functions


def python_functions(text):
    """(name, first line, last line) of each function at module or class level."""
    functions = []

    def visit(body, prefix):
        for node in body:
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                functions.append((prefix + node.name, node.lineno, node.end_lineno))
            elif isinstance(node, ast.ClassDef):
                visit(node.body, prefix + node.name + ".")

    visit(ast.parse(text).body, "")
    return functions

//! The C compiler's view of NavLink's headers, for the layout test. Struct and field names come from
//! the headers (a small parser of `typedef struct NAME { ... } NAME;` and of `#define NAME <integer>`),
//! sizes, alignments, offsets and values from a C program compiled with the system C compiler and run.
//! The program prints Rust: one `c_struct!` per struct, one `c_init!` per inline initialiser
//! (`NL_DEFINE_OUTPUT_INIT(T, name)`, with the `size` that calling it sets) and one `c_constant!` per
//! integer constant, which tests/layout.rs expands into checks against navlink-sys's own definitions.
use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

const HEADERS: [&str; 4] = ["navlink/version.h", "navlink/navlink.h", "navlink/recast.h", "navlink/plugin.h"];

/// The parts an umbrella header includes (`#include "navlink/X.h"`, in order), but export.h and version.h.
fn parts_of(text: &str) -> Vec<String> {
    text.lines()
        .filter_map(|line| line.trim().strip_prefix("#include \"navlink/"))
        .filter_map(|rest| rest.strip_suffix('"'))
        .filter(|name| *name != "export.h" && *name != "version.h")
        .map(|name| format!("navlink/{}", name))
        .collect()
}

pub fn run(include_dirs: &[PathBuf], out_dir: &Path, compiler: &str) -> Result<String, String> {
    let mut structs = Vec::new();
    let mut constants = Vec::new();
    let mut inits = Vec::new();
    let mut headers: Vec<String> = HEADERS.iter().map(|h| h.to_string()).collect();
    let mut next = 0;
    while next < headers.len() {
        let header = headers[next].clone();
        next += 1;
        let path = include_dirs
            .iter()
            .map(|d| d.join(&header))
            .find(|p| p.is_file())
            .ok_or_else(|| format!("{} is in none of {:?}", header, include_dirs))?;
        let raw = fs::read_to_string(&path).map_err(|e| format!("{}: {}", path.display(), e))?;
        for (k, part) in parts_of(&raw).into_iter().enumerate() {
            if !headers.contains(&part) {
                headers.insert(next + k, part);  // navlink.h's parts, read where it includes them
            }
        }
        let text = strip_comments(&raw);
        structs.extend(parse_structs(&text)?);
        constants.extend(parse_integer_defines(&text));
        inits.extend(parse_output_inits(&text));
    }
    let source = out_dir.join("c_layout_probe.c");
    let exe = out_dir.join("c_layout_probe");
    fs::write(&source, probe_program(&structs, &inits, &constants)).map_err(|e| e.to_string())?;
    let mut cc = Command::new(compiler);
    cc.args(["-std=c11", "-Wall", "-Werror", "-o"]).arg(&exe).arg(&source);
    for dir in include_dirs {
        cc.arg("-I").arg(dir);
    }
    let built = cc.output().map_err(|e| format!("{}: {}", compiler, e))?;
    if !built.status.success() {
        return Err(format!("{} failed: {}", compiler, String::from_utf8_lossy(&built.stderr)));
    }
    let ran = Command::new(&exe).output().map_err(|e| e.to_string())?;
    if !ran.status.success() {
        return Err("the probe program failed".to_string());
    }
    String::from_utf8(ran.stdout).map_err(|e| e.to_string())
}

fn strip_comments(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(i) = rest.find('/') {
        out.push_str(&rest[..i]);
        let tail = &rest[i..];
        if let Some(after) = tail.strip_prefix("/*") {
            rest = after.find("*/").map(|j| &after[j + 2..]).unwrap_or("");
            out.push(' ');
        } else if tail.starts_with("//") {
            rest = tail.find('\n').map(|j| &tail[j..]).unwrap_or("");
        } else {
            out.push('/');
            rest = &tail[1..];
        }
    }
    out.push_str(rest);
    out
}

fn is_ident(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_'
}

/// The last identifier of a declaration, after removing array brackets: `float origin[3]` -> origin.
fn declared_name(decl: &str) -> Option<String> {
    if let Some(i) = decl.find("(*") {
        // A pointer to function: `nl_status (*name)(...)`.
        let name: String = decl[i + 2..].trim_start().chars().take_while(|&c| is_ident(c)).collect();
        return if name.is_empty() { None } else { Some(name) };
    }
    let without_arrays: String = decl.split('[').next().unwrap_or("").to_string();
    let name: String = without_arrays.trim_end().chars().rev().take_while(|&c| is_ident(c)).collect();
    if name.is_empty() { None } else { Some(name.chars().rev().collect()) }
}

type Struct = (String, Vec<String>);

fn parse_structs(text: &str) -> Result<Vec<Struct>, String> {
    let mut structs = Vec::new();
    let mut rest = text;
    while let Some(i) = rest.find("typedef struct") {
        rest = &rest[i + "typedef struct".len()..];
        let name: String = rest.trim_start().chars().take_while(|&c| is_ident(c)).collect();
        let after_name = rest.trim_start()[name.len()..].trim_start();
        if !after_name.starts_with('{') {
            continue; // an opaque declaration such as `typedef struct nl_world nl_world;`
        }
        let close = after_name.find('}').ok_or("unclosed struct")?;
        let body = &after_name[1..close];
        let mut fields = Vec::new();
        for decl in body.split(';') {
            let decl = decl.split_whitespace().collect::<Vec<_>>().join(" ");
            if decl.is_empty() {
                continue;
            }
            if !decl.contains("(*") && decl.contains(',') {
                return Err(format!("{}: several fields in one declaration: {}", name, decl));
            }
            fields.push(declared_name(&decl).ok_or_else(|| format!("{}: cannot read `{}`", name, decl))?);
        }
        structs.push((name, fields));
        rest = &after_name[close..];
    }
    Ok(structs)
}

/// `NL_DEFINE_OUTPUT_INIT(T, name)` uses (not the macro's own `#define`): (T, name) each.
fn parse_output_inits(text: &str) -> Vec<(String, String)> {
    let mut inits = Vec::new();
    for line in text.lines() {
        let args = match line.trim_start().strip_prefix("NL_DEFINE_OUTPUT_INIT(") {
            Some(rest) => rest.split(')').next().unwrap_or(""),
            None => continue,
        };
        let names: Vec<&str> = args.split(',').map(str::trim).collect();
        if names.len() == 2 && names.iter().all(|n| !n.is_empty() && n.chars().all(is_ident)) {
            inits.push((names[0].to_string(), names[1].to_string()));
        }
    }
    inits
}

/// `#define NL_NAME value` where value is an integer literal, maybe negative, suffixed or parenthesised.
fn parse_integer_defines(text: &str) -> Vec<String> {
    let mut names = Vec::new();
    for line in text.lines() {
        let mut words = line.split_whitespace();
        if words.next() != Some("#define") {
            continue;
        }
        let (name, value) = match (words.next(), words.next()) {
            (Some(n), Some(v)) if words.next().is_none() => (n, v),
            _ => continue,
        };
        let digits = value.trim_start_matches('(').trim_end_matches(')').trim_start_matches('-').trim_end_matches('u');
        let is_integer = digits.strip_prefix("0x").map_or(!digits.is_empty() && digits.chars().all(|c| c.is_ascii_digit()), |hex| {
            !hex.is_empty() && hex.chars().all(|c| c.is_ascii_hexdigit())
        });
        if name.starts_with("NL_") && is_integer {
            names.push(name.to_string());
        }
    }
    names
}

fn probe_program(structs: &[Struct], inits: &[(String, String)], constants: &[String]) -> String {
    let mut c = String::new();
    for header in HEADERS {
        c += &format!("#include <{}>\n", header);
    }
    c += "#include <stddef.h>\n#include <stdio.h>\n\nint main(void) {\n";
    // One block: include! in expression position takes a single expression.
    c += "    printf(\"{{\\n\");\n";
    for (name, fields) in structs {
        c += &format!("    printf(\"c_struct!({0}, %zu, %zu, [\\n\", sizeof({0}), _Alignof({0}));\n", name);
        for f in fields {
            c += &format!(
                "    printf(\"    ({1}, %zu, %zu),\\n\", offsetof({0}, {1}), sizeof((({0}*)0)->{1}));\n",
                name, f
            );
        }
        c += "    printf(\"]);\\n\");\n";
    }
    for (name, init) in inits {
        c += &format!("    printf(\"c_init!({0}, {1}, %u);\\n\", (unsigned)({1}().size));\n", name, init);
    }
    for k in constants {
        c += &format!("    printf(\"c_constant!({0}, %lldi64);\\n\", (long long)({0}));\n", k);
    }
    c += "    printf(\"}}\\n\");\n    return 0;\n}\n";
    c
}

//! Baked navmesh files: saved to bytes and to a file, described, loaded into a new world (the same
//! polygons, links and paths); truncated and foreign bytes refused with nothing added.
mod common;

use common::*;
use navlink::{
    default_agent_type, default_link_def, describe_navmesh_file, status, NavmeshBuild, NavmeshId,
    NavmeshLoadOptions, PathOutcome, PathQuery, World,
};

/// A JSON value, parsed by a small reader here (the workspace has no dependencies).
#[derive(Debug, PartialEq)]
enum Json {
    Null,
    Bool(bool),
    Number(f64),
    String(String),
    Array(Vec<Json>),
    Object(Vec<(String, Json)>),
}

impl Json {
    fn get(&self, key: &str) -> Option<&Json> {
        match self {
            Json::Object(members) => members.iter().find(|(k, _)| k == key).map(|(_, v)| v),
            _ => None,
        }
    }
}

/// The JSON text as one value (and nothing after it), or why not.
fn parse_json(text: &str) -> Result<Json, String> {
    let mut reader = JsonReader { bytes: text.as_bytes(), at: 0 };
    let value = reader.value()?;
    reader.space();
    if reader.at != reader.bytes.len() {
        return Err(format!("text after the value at {}", reader.at));
    }
    Ok(value)
}

struct JsonReader<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl<'a> JsonReader<'a> {
    fn space(&mut self) {
        while self.at < self.bytes.len() && b" \t\r\n".contains(&self.bytes[self.at]) {
            self.at += 1;
        }
    }

    fn eat(&mut self, byte: u8) -> Result<(), String> {
        self.space();
        if self.bytes.get(self.at) == Some(&byte) {
            self.at += 1;
            Ok(())
        } else {
            Err(format!("expected '{}' at {}", byte as char, self.at))
        }
    }

    fn word(&mut self, word: &str, value: Json) -> Result<Json, String> {
        if self.bytes[self.at..].starts_with(word.as_bytes()) {
            self.at += word.len();
            Ok(value)
        } else {
            Err(format!("bad literal at {}", self.at))
        }
    }

    fn value(&mut self) -> Result<Json, String> {
        self.space();
        match self.bytes.get(self.at) {
            Some(b'n') => self.word("null", Json::Null),
            Some(b't') => self.word("true", Json::Bool(true)),
            Some(b'f') => self.word("false", Json::Bool(false)),
            Some(b'"') => self.string().map(Json::String),
            Some(b'[') => {
                self.at += 1;
                let mut items = Vec::new();
                self.space();
                if self.bytes.get(self.at) == Some(&b']') {
                    self.at += 1;
                    return Ok(Json::Array(items));
                }
                loop {
                    items.push(self.value()?);
                    self.space();
                    if self.bytes.get(self.at) == Some(&b',') {
                        self.at += 1;
                    } else {
                        self.eat(b']')?;
                        return Ok(Json::Array(items));
                    }
                }
            }
            Some(b'{') => {
                self.at += 1;
                let mut members = Vec::new();
                self.space();
                if self.bytes.get(self.at) == Some(&b'}') {
                    self.at += 1;
                    return Ok(Json::Object(members));
                }
                loop {
                    self.space();
                    let key = self.string()?;
                    self.eat(b':')?;
                    members.push((key, self.value()?));
                    self.space();
                    if self.bytes.get(self.at) == Some(&b',') {
                        self.at += 1;
                    } else {
                        self.eat(b'}')?;
                        return Ok(Json::Object(members));
                    }
                }
            }
            Some(c) if *c == b'-' || c.is_ascii_digit() => {
                let start = self.at;
                while self.at < self.bytes.len() && b"+-.eE0123456789".contains(&self.bytes[self.at]) {
                    self.at += 1;
                }
                let text = std::str::from_utf8(&self.bytes[start..self.at]).unwrap();
                text.parse().map(Json::Number).map_err(|_| format!("bad number '{}'", text))
            }
            _ => Err(format!("no value at {}", self.at)),
        }
    }

    /// A string without escapes beyond \" \\ \/ and the one-letter ones (enough for these files).
    fn string(&mut self) -> Result<String, String> {
        if self.bytes.get(self.at) != Some(&b'"') {
            return Err(format!("expected a string at {}", self.at));
        }
        self.at += 1;
        let mut out = Vec::new();
        loop {
            match self.bytes.get(self.at) {
                None => return Err("unterminated string".into()),
                Some(b'"') => {
                    self.at += 1;
                    return String::from_utf8(out).map_err(|e| e.to_string());
                }
                Some(b'\\') => {
                    let escaped = *self.bytes.get(self.at + 1).ok_or("unterminated escape")?;
                    out.push(match escaped {
                        b'n' => b'\n',
                        b't' => b'\t',
                        b'r' => b'\r',
                        b'b' => 8,
                        b'f' => 12,
                        b'"' | b'\\' | b'/' => escaped,
                        _ => return Err(format!("unsupported escape at {}", self.at)),
                    });
                    self.at += 2;
                }
                Some(&c) => {
                    out.push(c);
                    self.at += 1;
                }
            }
        }
    }
}

#[test]
fn baked_navmesh_file() {
    let world = World::new().unwrap();
    add_gap_level(&world);
    let navmesh = world.build_navmesh(&NavmeshBuild::new(default_agent_type())).unwrap();
    world.generate_links(navmesh, None, None, None).unwrap();
    let manual = navlink::LinkDef { start: [-5.0, 0.0, 4.0], end: [5.0, 0.0, 4.0], ..default_link_def() };
    world.add_link(navmesh, &manual).unwrap();
    let link_count = world.links(navmesh).unwrap().len() as u32;
    let polygons = world.navmesh_info(navmesh).unwrap().polygon_count;
    let original = world.find_path(&PathQuery::new(navmesh, WEST, EAST, jumper())).unwrap();
    assert_eq!(original.outcome(), PathOutcome::Complete);
    let data: Vec<u8> = world.save_navmesh(navmesh).unwrap();

    let (info, made_for) = describe_navmesh_file(&data).unwrap();
    assert_eq!(info.file_size, data.len() as u64);
    assert!(info.version >= 1, "version {}", info.version);
    assert_eq!(info.polygon_count, polygons);
    assert_eq!((info.link_count, info.generated_link_count), (link_count, link_count - 1));
    assert!((info.agent_type.radius - 0.6).abs() < 1e-6, "radius {}", info.agent_type.radius);
    assert_eq!(info.quantum, 1.0 / 1024.0);
    assert!(!info.rides_carrier);
    let made_for = parse_json(&made_for).unwrap_or_else(|e| panic!("made-for JSON {}: {}", made_for, e));
    assert_eq!(made_for.get("builder"), Some(&Json::String("recast".into())));
    assert_eq!(made_for.get("level_hash"), Some(&Json::String(format!("{:016x}", info.level_hash))));

    let check_same = |w: &World, loaded: NavmeshId| {
        assert_eq!(w.navmesh_info(loaded).unwrap().polygon_count, polygons);
        assert_eq!(w.links(loaded).unwrap().len() as u32, link_count);
        let path = w.find_path(&PathQuery::new(loaded, WEST, EAST, jumper())).unwrap();
        assert_eq!(path.outcome(), PathOutcome::Complete);
        assert!((path.summary.length - original.summary.length).abs() < 1e-4, "{} m, {} m", path.summary.length, original.summary.length);
    };

    let fresh = World::new().unwrap();
    let loaded = fresh.load_navmesh(&data, &NavmeshLoadOptions::default()).unwrap();
    check_same(&fresh, loaded);
    assert_eq!(fresh.save_navmesh(loaded).unwrap(), data, "what it was made for travels with it");

    let dir = TempDir::new("navmesh-file");
    let path = dir.0.join("gap.nlnav");
    world.save_navmesh_file(navmesh, &path).unwrap();
    assert_eq!(std::fs::read(&path).unwrap(), data);
    let from_file = World::new().unwrap();
    check_same(&from_file, from_file.load_navmesh_file(&path, &NavmeshLoadOptions::default()).unwrap());

    // The level it was baked from: same_level refuses a world without it, takes one with it.
    let other = World::new().unwrap();
    let same_level = NavmeshLoadOptions { same_level: true, ..Default::default() };
    assert_fails(other.load_navmesh(&data, &same_level), status::INVALID_ARGUMENT, "baked from");
    assert!(other.navmeshes().unwrap().is_empty());
    add_gap_level(&other);
    check_same(&other, other.load_navmesh(&data, &same_level).unwrap());

    let count = other.navmeshes().unwrap().len();
    let none = NavmeshLoadOptions::default();
    assert_fails(other.load_navmesh(&data[..data.len() / 2], &none), status::PARSE_ERROR, "nl_navmesh_load");
    assert_fails(other.load_navmesh(b"hello", &none), status::VERSION_MISMATCH, "nl_navmesh_load");
    assert_fails(describe_navmesh_file(&data[..data.len() / 2]), status::PARSE_ERROR, "nl_navmesh_file_describe");
    assert_fails(describe_navmesh_file(b"hello"), status::VERSION_MISMATCH, "nl_navmesh_file_describe");
    assert_fails(other.load_navmesh_file(dir.0.join("missing.nlnav"), &none), status::NOT_FOUND, "nl_navmesh_load_file");
    assert_eq!(other.navmeshes().unwrap().len(), count, "nothing added on failure");
}

#[test]
fn json_reader_reads_what_it_should() {
    let value = parse_json(r#" {"a": [1, -2.5e3, true, null], "b": {"c": "x\"y"}, "d": false} "#).unwrap();
    assert_eq!(value.get("a"), Some(&Json::Array(vec![Json::Number(1.0), Json::Number(-2500.0), Json::Bool(true), Json::Null])));
    assert_eq!(value.get("b").and_then(|b| b.get("c")), Some(&Json::String("x\"y".into())));
    assert_eq!(value.get("d"), Some(&Json::Bool(false)));
    for bad in ["", "{", "{\"a\" 1}", "[1,]", "{} x", "nul"] {
        assert!(parse_json(bad).is_err(), "'{}' is not JSON", bad);
    }
}

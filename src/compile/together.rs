//! Stage texts of one pass parsed together: naga parses the declarations its variants share once,
//! then each variant's module is cut out of the one it made, the same as naga makes from the
//! variant's own text (a pass's fragment variants share the lighting library and differ in a
//! function or two, so most of each parse was the same work).
//!
//! Each text's declarations ([`reach`]'s scan) are told apart by their text and what they name:
//! a declaration that is the same, naming the same declarations, in several texts is written once.
//! Where a name stands for different declarations, each is written under a name of its own
//! (`GetNormal` as `GetNormal_kIlN4`) and the names are given back once a variant's module is cut
//! out. What calls a function is written once for all its meanings of one head (parameters and
//! result): naga lowers a call from the head alone, so the caller calls the first of them in the
//! text, and each variant's own function is put in that one's place when its module is cut out.
//! The declarations go in an order that keeps every text's own (its dependency order, which
//! naga lowers it in), each after a marker (`alias kIlN_m7 = f32;`), so that the type naga makes
//! first for a declaration can be traced to it.
//!
//! A variant's module is the parse's, with its entry point only, the constants of other texts
//! unnamed, compacted: naga lowers a declaration the same wherever it is, so this is the module
//! its own text gives, compacted, unless a type it keeps was made first for another text's
//! declaration (types are numbered in the order naga meets them). Then that variant is left to its
//! own parse, as is every text the scan cannot vouch for: one that names what another text
//! declares and it does not (its parse would fail), one that declares a name inside a declaration
//! under a name written anew, one with other directives than the rest, a `const_assert`, a
//! `diagnostic` filter or `@align`/`@size`.
//!
//! **Invariant (naga's order):** a module cut out of the joint parse is byte for byte the module
//! the variant's own text gives only because naga 30 numbers types, constants and functions in
//! the order it meets their declarations, and lowers a declaration alike wherever it stands. A
//! naga that renumbered would break it silently, so it is guarded three ways: `head_types` reads
//! the types naga makes for a function's head from a parse of that head alone, and a variant whose
//! types would come out in another order is left to its own parse; the unit proptest
//! `every_module_cut_out_is_its_own_text_s` compares each cut module with naga's parse of its own
//! text, byte for byte; and `tests/it/together.rs` builds every fixture and a generated library
//! both ways and compares the written bytes
//! (`every_fixture_writes_the_same_bytes_parsed_together_as_alone`,
//! `variants_whose_names_mean_other_things_write_what_they_write_alone`). Raising naga means
//! running those first.
//!
//! Long because it is one algorithm with one data structure: the joint text is written, parsed
//! and cut by the same tables (which declaration is whose, under which name, after which
//! marker); split, each part would need the others' private tables.

use super::panics::contain_panics;
use super::reach::{self, Declaration, Kind, Names};
use std::sync::OnceLock;
// Every text of a build's passes goes through these maps: a fast hash.
type HashMap<K, V> = std::collections::HashMap<K, V, foldhash::fast::FixedState>;
type HashSet<T> = std::collections::HashSet<T, foldhash::fast::FixedState>;

/// What names written anew and markers start or contain; a text with it is parsed alone.
const MARK: &str = "kIlN";

/// The most texts parsed together: each variant's module is cut from a copy of the one parse,
/// which holds every member's own declarations.
pub(crate) const MOST_TEXTS: usize = 16;

/// Texts parsed together, once naga has parsed [`Together::text`].
pub(crate) struct Together {
    /// What naga parses.
    pub(crate) text: String,
    /// Each text given, in order: how to cut its module out, or `None` where it is left to its
    /// own parse.
    members: Vec<Option<Member>>,
    /// Each declaration written, in the text's order (its marker's number is its index).
    placed: Vec<Placed>,
    /// The bytes of the texts it parses together.
    given: usize,
    /// The types naga makes for each placed function's head alone ([`head_order`]), read once
    /// for all the members that ask (a batch's kernels share their entry points' heads).
    heads: Vec<OnceLock<Option<Vec<naga::TypeInner>>>>,
}

/// Where a declaration is in the text parsed, and how its names written anew moved what follows
/// them: (where a renamed name ends in the text parsed, how many bytes it added), in order.
struct Placed {
    at: usize,
    shifts: Vec<(usize, isize)>,
    /// For a function whose head names no declaration (so that naga reads it the same alone),
    /// where its body starts in the text parsed.
    body: Option<usize>,
}

impl Placed {
    /// Where `offset`, in the text parsed, is in the declaration as its texts have it (from its
    /// start).
    fn original(&self, offset: usize) -> Option<usize> {
        let relative = offset.checked_sub(self.at)?;
        let before = self.shifts.iter().take_while(|(end, _)| *end <= offset).last();
        relative.checked_add_signed(-before.map_or(0, |(_, shift)| *shift))
    }
}

/// One text's part of a parse together.
pub(crate) struct Member {
    /// Its entry point's name in the text parsed.
    entry: String,
    /// Where the declarations written for it are in its own text, by their place in the text
    /// parsed.
    declarations: HashMap<usize, usize>,
    /// The names its declarations have in the text parsed.
    names: HashSet<String>,
    /// Names written anew, with the names they are given back.
    renamed: Vec<(String, String)>,
    /// Declarations of other texts it may take types from, with its own they stand for (both by
    /// their place in the text parsed): each right before its own, lowered alike.
    counterparts: HashMap<usize, usize>,
    /// Its functions: by the place of the function its module has there (the first of its class),
    /// the place of its own.
    functions: HashMap<usize, usize>,
    /// Whether it calls a built-in whose result is a type naga makes once for all (`modf`).
    meets_predeclared: bool,
}

/// The built-ins whose results are types naga makes the first time one is called and keeps in
/// `special_types`.
const MAKE_PREDECLARED: [&str; 3] = ["modf", "frexp", "atomicCompareExchangeWeak"];

/// A text's declarations as the parse together tells them apart.
struct Scanned<'t> {
    scan: reach::Scan<'t>,
    /// Its declarations in dependency order, each as the one written.
    order: Vec<usize>,
    /// Where each of those starts in the text.
    starts: Vec<usize>,
    /// Its directives (`enable`, `requires`): they go first in the text parsed together.
    directives: Vec<&'t str>,
}

/// The one declaration written for each equal declaration of the texts: its text, what it names
/// (as written), and its name.
struct Written<'t> {
    text: &'t str,
    /// Where in `text` each identifier to be renamed is, with the index of what it names.
    names: Vec<(std::ops::Range<usize>, usize)>,
    name: Option<&'t str>,
    kind: Kind,
    /// For a function, the first function written with its name and head (parameters and
    /// result, the same text naming the same declarations); else itself. naga lowers a call the
    /// same whichever of those it calls, so what calls one is written once, calling the first
    /// of them in the text, and each member's own is put in that one's place when its module
    /// is cut out.
    class: usize,
}

/// The declarations written so far, and how to find them.
#[derive(Default)]
struct Writing<'t> {
    written: Vec<Written<'t>>,
    /// A written declaration by its text and the classes of the declarations it names.
    identity: HashMap<(&'t str, Vec<usize>), usize>,
    /// A function's class by its name, its head's text and what its head names.
    classes: HashMap<(&'t str, &'t str, Vec<usize>), usize>,
}

/// A stage text to parse together with others.
pub(crate) struct Text<'t> {
    pub text: &'t str,
    /// Its entry point's name.
    pub entry: &'t str,
    /// Its scan, where the cut made one (else it is scanned here).
    pub scan: Option<&'t reach::CutScan>,
}

/// Assembles one text for naga from `texts`, or `None` where fewer than two of them can share a
/// parse.
pub(crate) fn assemble(texts: &[Text]) -> Option<Together> {
    if texts.len() < 2 {
        return None;
    }
    let mut writing = Writing::default();
    let mut scanned: Vec<Option<Scanned>> = texts.iter().map(|text| scan(text, &mut writing)).collect();
    let written = writing.written;
    // The texts parsed together have the same directives: those most of them have.
    let mut counts: HashMap<&[&str], usize> = HashMap::default();
    for s in scanned.iter().flatten() {
        *counts.entry(&s.directives).or_default() += 1;
    }
    let directives: Vec<&str> = counts
        .into_iter()
        .max_by_key(|&(key, n)| (n, std::cmp::Reverse(key)))
        .map(|(key, _)| key.to_vec())
        .unwrap_or_default();
    for one in scanned.iter_mut() {
        if one.as_ref().is_some_and(|s| s.directives != directives) {
            *one = None;
        }
    }
    // Names that stand for more than one declaration are written anew for each.
    let mut meanings: HashMap<&str, usize> = HashMap::default();
    for w in &written {
        if let Some(name) = w.name {
            *meanings.entry(name).or_default() += 1;
        }
    }
    let renamed = |index: usize| -> Option<String> {
        let name = written[index].name?;
        (meanings[name] > 1).then(|| format!("{name}_{MARK}{index}"))
    };
    let declared_anywhere: HashSet<&str> = meanings.keys().copied().collect();
    // Texts whose parse together could differ from their own are left to it.
    for one in scanned.iter_mut() {
        let Some(s) = one else { continue };
        let own: HashSet<&str> = s.scan.declarations.iter().filter_map(|d| d.name).collect();
        let foreign = |word: &&str| declared_anywhere.contains(word) && !own.contains(word);
        let renamed_here: HashSet<&str> =
            s.order.iter().filter(|&&w| renamed(w).is_some()).filter_map(|&w| written[w].name).collect();
        if s.scan.uses.iter().any(foreign)
            || s.scan.locals.iter().any(|w| foreign(w) || renamed_here.contains(w))
        {
            *one = None;
        }
    }
    // One order of names that keeps each text's own (or the text is left to its own parse); the
    // declarations of a name go together, in the order the texts give them: a text's own
    // declaration comes right after the other meanings of its name before it (its counterparts).
    let mut names: Vec<&str> = Vec::new();
    let mut rank: HashMap<&str, usize> = HashMap::default();
    for one in scanned.iter_mut() {
        let Some(s) = one else { continue };
        let own: Vec<&str> = s.order.iter().filter_map(|&w| written[w].name).collect();
        let Some(merged) = merge(&names, &rank, &own) else {
            *one = None;
            continue;
        };
        names = merged;
        rank = names.iter().enumerate().map(|(at, &name)| (name, at)).collect();
    }
    if scanned.iter().flatten().count() < 2 {
        return None;
    }
    let mut meaning_of: HashMap<&str, Vec<usize>> = HashMap::default();
    for s in scanned.iter().flatten() {
        for &w in &s.order {
            let meanings = meaning_of.entry(written[w].name.unwrap_or_default()).or_default();
            if !meanings.contains(&w) {
                meanings.push(w);
            }
        }
    }
    let order: Vec<usize> = names.iter().flat_map(|name| meaning_of[name].iter().copied()).collect();
    let position: HashMap<usize, usize> = order.iter().enumerate().map(|(at, &w)| (w, at)).collect();
    // What is written calling a function calls the first of its class in the text.
    let mut first_of_class: HashMap<usize, usize> = HashMap::default();
    for &w in &order {
        first_of_class.entry(written[w].class).or_insert(w);
    }
    let mut text = String::new();
    for directive in directives {
        text.push_str(directive);
        text.push('\n');
    }
    let mut placed = Vec::with_capacity(order.len());
    for (marker, &w) in order.iter().enumerate() {
        text.push_str(&format!("alias {MARK}_m{marker} = f32;\n"));
        let declaration = &written[w];
        let (mut at, mut shift, mut shifts) = (0, 0isize, Vec::new());
        let start = text.len();
        for (range, named) in &declaration.names {
            text.push_str(&declaration.text[at..range.start]);
            let named = match *named == w {
                true => w,
                false => first_of_class.get(&written[*named].class).copied().unwrap_or(*named),
            };
            match renamed(named) {
                Some(name) => {
                    text.push_str(&name);
                    shift += name.len() as isize - range.len() as isize;
                    shifts.push((text.len(), shift));
                }
                None => text.push_str(&declaration.text[range.clone()]),
            }
            at = range.end;
        }
        text.push_str(&declaration.text[at..]);
        text.push('\n');
        let head_end = declaration.text.find('{').filter(|&end| {
            declaration.kind == Kind::Function
                && !declaration.names.iter().any(|(r, n)| r.end <= end && *n != w)
        });
        let body = head_end.and_then(|_| text[start..].find('{')).map(|body| start + body);
        placed.push(Placed { at: start, shifts, body });
    }
    let members = scanned
        .iter()
        .zip(texts)
        .map(|(one, &Text { entry, .. })| {
            let s = one.as_ref()?;
            let names = s.order.iter().filter_map(|&w| renamed(w).or(written[w].name.map(str::to_string)));
            let renamed: Vec<(String, String)> =
                s.order.iter().filter_map(|&w| Some((renamed(w)?, written[w].name?.to_string()))).collect();
            let entry = renamed.iter().find(|(_, original)| original == entry).map_or(entry, |(new, _)| new);
            // The other meanings of each of its names before its own, where naga lowers them
            // alike: the types one made first are those its own would have.
            let mut counterparts = HashMap::default();
            for &own in &s.order {
                let name = written[own].name.unwrap_or_default();
                for &other in meaning_of[name].iter().take_while(|&&w| w != own) {
                    if lowered_alike(&written, other, own) {
                        counterparts.insert(position[&other], position[&own]);
                    }
                }
            }
            let functions = (s.order.iter().filter(|&&w| written[w].kind == Kind::Function))
                .map(|&w| (position[&first_of_class[&written[w].class]], position[&w]))
                .collect();
            Some(Member {
                counterparts,
                functions,
                meets_predeclared: s.scan.uses.iter().any(|w| MAKE_PREDECLARED.contains(w)),
                entry: entry.to_string(),
                declarations: (s.order.iter().zip(&s.starts))
                    .map(|(w, &start)| (position[w], start))
                    .collect(),
                names: names.collect(),
                renamed,
            })
        })
        .collect();
    let given = scanned.iter().zip(texts).filter(|(one, _)| one.is_some()).map(|(_, t)| t.text.len()).sum();
    let heads = placed.iter().map(|_| OnceLock::new()).collect();
    Some(Together { text, members, placed, given, heads })
}

/// One text's scan, its declarations made written ones; `None` where it cannot share a parse.
fn scan<'t>(given: &Text<'t>, writing: &mut Writing<'t>) -> Option<Scanned<'t>> {
    let (text, entry) = (given.text, given.entry);
    if text.contains(MARK) || text.contains("diagnostic") || text.contains("const_assert") {
        return None;
    }
    if super::layout::has_layout_attribute(text) {
        return None;
    }
    let scan = match given.scan {
        Some(scan) => scan.of(text)?,
        None => reach::declarations(text)?,
    };
    let declarations = &scan.declarations;
    let mut by_name: Names = HashMap::with_capacity_and_hasher(declarations.len(), Default::default());
    let mut directives = Vec::new();
    for (index, d) in declarations.iter().enumerate() {
        match d.name {
            Some(name) if by_name.insert(name, index).is_some() => return None,
            Some(_) => {}
            // Directives go first in the text parsed; any other form the scan does not know
            // might not.
            None if d.kind == Kind::Other => {
                let directive = &text[d.range.clone()];
                if !(directive.starts_with("enable") || directive.starts_with("requires")) {
                    return None;
                }
                directives.push(directive);
            }
            None => return None,
        }
    }
    let root = *by_name.get(entry)?;
    if declarations[root].kind != Kind::Function {
        return None;
    }
    let mut as_written: Vec<Option<usize>> = vec![None; declarations.len()];
    let (mut order, mut starts) =
        (Vec::with_capacity(declarations.len()), Vec::with_capacity(declarations.len()));
    for d in reach::dependency_order(declarations, &scan.uses, &by_name) {
        if declarations[d].kind == Kind::Other {
            continue;
        }
        let w = write(text, &declarations[d], &scan, &by_name, &as_written, writing)?;
        as_written[d] = Some(w);
        order.push(w);
        starts.push(declarations[d].range.start);
    }
    Some(Scanned { scan, order, starts, directives })
}

/// The written declaration for `d`: an equal one already written, or `d` as a new one. `None`
/// where it names a declaration not yet written (a cycle, which naga refuses).
fn write<'t>(
    text: &'t str,
    d: &Declaration<'t>,
    scan: &reach::Scan<'t>,
    by_name: &Names,
    as_written: &[Option<usize>],
    writing: &mut Writing<'t>,
) -> Option<usize> {
    let source = &text[d.range.clone()];
    let offset = |word: &str| word.as_ptr() as usize - source.as_ptr() as usize;
    let mut names = Vec::new();
    if let Some(name) = d.name {
        let at = offset(name);
        // Its own name is written as what it declares.
        names.push((at..at + name.len(), usize::MAX));
    }
    let mut named = Vec::new();
    for word in &scan.uses[d.uses.clone()] {
        if let Some(&used) = by_name.get(word) {
            let w = as_written[used]?;
            let at = offset(word);
            names.push((at..at + word.len(), w));
            named.push(writing.written[w].class);
        }
    }
    names.sort_by_key(|(range, _)| range.start);
    let index = writing.written.len();
    let index = *writing.identity.entry((source, named)).or_insert(index);
    if index == writing.written.len() {
        for name in names.iter_mut().filter(|(_, w)| *w == usize::MAX) {
            name.1 = index;
        }
        let class = match (d.kind, d.name, source.find('{')) {
            (Kind::Function, Some(name), Some(body)) => {
                let head = names.iter().filter(|(r, w)| r.end <= body && *w != index).map(|(_, w)| *w);
                *writing.classes.entry((name, &source[..body], head.collect())).or_insert(index)
            }
            _ => index,
        };
        writing.written.push(Written { text: source, names, name: d.name, kind: d.kind, class });
    }
    Some(index)
}

/// `order` with `text`'s declarations in, each new one as late as it can go: after those before
/// it in `text`, before the next of them already in. `None` where `order` has two of them the
/// other way round.
fn merge<T: Copy + Eq + std::hash::Hash>(
    order: &[T],
    position: &HashMap<T, usize>,
    text: &[T],
) -> Option<Vec<T>> {
    let mut merged = Vec::with_capacity(order.len() + text.len());
    let (mut next, mut new) = (0, Vec::new());
    for &w in text {
        match position.get(&w) {
            Some(&at) if at < next => return None,
            Some(&at) => {
                merged.extend_from_slice(&order[next..at]);
                merged.append(&mut new);
                merged.push(w);
                next = at + 1;
            }
            None => new.push(w),
        }
    }
    merged.extend_from_slice(&order[next..]);
    merged.append(&mut new);
    Some(merged)
}

/// naga's module of the text parsed together, made ready to cut each member's out of.
pub(crate) struct Parsed {
    /// The module without its entry points and functions.
    template: naga::Module,
    /// Its functions, each with the declaration it was written for.
    functions: Vec<(naga::Function, naga::Span, Option<usize>)>,
    /// Which of `functions` was written for each declaration, by the declaration's place.
    function_at: HashMap<usize, usize>,
    entry_points: Vec<naga::EntryPoint>,
    /// The declaration each type was made for (by the type's index): the marker before it, or
    /// `None` before the first.
    made_for: Vec<Option<usize>>,
}

impl Together {
    /// The declaration written where `offset` is in the text parsed (its index in `placed`).
    fn place_of(&self, offset: usize) -> Option<usize> {
        self.placed.partition_point(|p| p.at <= offset).checked_sub(1)
    }
    /// Whether parsing the texts together saves a quarter of the parse or more: where each text's
    /// own declarations are most of it (small kernels that differ throughout), the cutting out
    /// costs what the shared parse saves.
    pub(crate) fn saves_enough(&self) -> bool {
        4 * self.text.len() <= 3 * self.given
    }

    /// naga's parse of [`Together::text`], readied for [`Together::cut`]. `None` where naga
    /// refuses it (or panics): no one's error here, as each text is then parsed alone and its own
    /// error, if it has one, reported.
    pub(crate) fn parse(&self) -> Option<Parsed> {
        // A function past the limit is refused when its own text is parsed, before naga's
        // quadratic cost: never parsed here first.
        if super::largest_function(&self.text).is_some_and(|(_, n)| n > super::MAX_FUNCTION_TERMS) {
            return None;
        }
        let module = contain_panics(|| naga::front::wgsl::parse_str(&self.text).ok()).ok().flatten()?;
        self.ready(module)
    }

    /// Each type's span set to its index (compaction keeps spans, so a type kept tells where it
    /// was made), the entry points set apart. `None` where the markers are not where they were
    /// written.
    fn ready(&self, mut module: naga::Module) -> Option<Parsed> {
        let mut made_for = Vec::with_capacity(module.types.len());
        let mut current = None;
        let mut types = naga::UniqueArena::new();
        for (handle, ty) in module.types.iter() {
            let marker =
                ty.name.as_deref().and_then(|n| n.strip_prefix(MARK)).and_then(|n| n.strip_prefix("_m"));
            if let Some(number) = marker {
                let number: usize = number.parse().ok()?;
                if current.map_or(0, |c| c + 1) != number {
                    return None;
                }
                current = Some(number);
            }
            made_for.push(current);
            let index = handle.index() as u32;
            types.insert(ty.clone(), naga::Span::new(index, index + 1));
        }
        if current.map_or(0, |c| c + 1) != self.placed.len() {
            return None;
        }
        module.types = types;
        let entry_points = std::mem::take(&mut module.entry_points);
        let functions: Vec<_> = (module.functions.drain())
            .map(|(_, function, span)| {
                let place = span.to_range().and_then(|r| self.place_of(r.start));
                (function, span, place)
            })
            .collect();
        let function_at =
            functions.iter().enumerate().filter_map(|(at, (.., place))| Some(((*place)?, at))).collect();
        Some(Parsed { template: module, functions, function_at, entry_points, made_for })
    }

    /// Member `index`'s module: what naga makes of its own text, compacted; `None` where it
    /// might differ (the member is then parsed alone).
    pub(crate) fn cut(
        &self,
        parsed: &Parsed,
        index: usize,
        stage: naga::ShaderStage,
    ) -> Option<naga::Module> {
        contain_panics(|| self.cut_unguarded(parsed, index, stage)).ok().flatten()
    }

    fn cut_unguarded(&self, parsed: &Parsed, index: usize, stage: naga::ShaderStage) -> Option<naga::Module> {
        let member = self.members.get(index)?.as_ref()?;
        let entry = parsed.entry_points.iter().find(|e| e.name == member.entry && e.stage == stage)?;
        let mut module = parsed.template.clone();
        // Each of its functions goes in the place of the first of its class, which is what its
        // callers call. The others stay as empty ones, so that handles keep their meaning:
        // nothing of this member's calls them, and compaction drops them.
        for (_, span, place) in &parsed.functions {
            let own =
                place.and_then(|p| member.functions.get(&p)).and_then(|own| parsed.function_at.get(own));
            let (function, span) = match own {
                Some(&own) => (parsed.functions[own].0.clone(), parsed.functions[own].1),
                None => (naga::Function::default(), *span),
            };
            module.functions.append(function, span);
        }
        module.entry_points.push(entry.clone());
        let mine = |made_for: Option<usize>| made_for.is_none_or(|d| member.declarations.contains_key(&d));
        for (_, constant) in module.constants.iter_mut() {
            if constant.name.as_ref().is_some_and(|name| !member.names.contains(name)) {
                constant.name = None;
            }
        }
        let predeclared = module.special_types.predeclared_types.len();
        module.special_types.predeclared_types.retain(|_, ty| mine(parsed.made_for[ty.index()]));
        // One it uses may be another's: alone it would have made it in its own place.
        if member.meets_predeclared && module.special_types.predeclared_types.len() < predeclared {
            return None;
        }
        naga::compact::compact(&mut module, naga::compact::KeepUnused::No);
        if !numbered_as_alone(&module, &parsed.made_for, member, |place| self.head_types(place)) {
            return None;
        }
        give_names_back(&mut module, &member.renamed);
        self.place_globals(&mut module, member)?;
        Some(module)
    }

    /// The types naga makes for the head (attributes, name, parameters and result) of the
    /// function written at `place`, read as a function of its own with an empty body; `None` where
    /// it is not a function or its head names a declaration (one that could shadow a predeclared
    /// type).
    fn head_types(&self, place: usize) -> Option<&[naga::TypeInner]> {
        let placed = self.placed.get(place)?;
        let head = || head_order(&format!("{}{{}}\n", &self.text[placed.at..placed.body?]));
        self.heads.get(place)?.get_or_init(head).as_deref()
    }

    /// The spans of a member's global variables moved into its own text, where its resources'
    /// declarations are reported from (`bind::Declared`); the rest are only read for errors,
    /// which the member's own parse reports.
    fn place_globals(&self, module: &mut naga::Module, member: &Member) -> Option<()> {
        let mut globals = naga::Arena::new();
        for (handle, global) in module.global_variables.iter() {
            let span = match module.global_variables.get_span(handle).to_range() {
                Some(range) => {
                    let place = self.place_of(range.start)?;
                    let own = member.declarations.get(&place)?;
                    let placed = &self.placed[place];
                    let (start, end) = (placed.original(range.start)?, placed.original(range.end)?);
                    naga::Span::new((own + start) as u32, (own + end) as u32)
                }
                None => naga::Span::UNDEFINED,
            };
            globals.append(global.clone(), span);
        }
        module.global_variables = globals;
        Some(())
    }
}

/// Whether a member's types, compacted, are numbered as its own text's would be. naga numbers
/// types in the order it first meets them, and in the text parsed together another text's
/// declaration may have met one first. That is harmless where that declaration is a counterpart
/// of the member's own (right before it, lowered alike) and the member's own made none of the
/// types it keeps: alone, its own would have met them in the same order. And it is harmless for
/// one such type only, where none of the member's declarations after that one made a type it
/// keeps. Last, for types met first by other texts' declarations that are all before the
/// member's next own one, where that one is the first of the member's to meet them all in its
/// head: alone, that head makes them, in the order [`head_order`] finds.
fn numbered_as_alone<'m>(
    module: &naga::Module,
    made_for: &[Option<usize>],
    member: &Member,
    head_types: impl Fn(usize) -> Option<&'m [naga::TypeInner]>,
) -> bool {
    let mut makers = Vec::with_capacity(module.types.len());
    for (ty, _) in module.types.iter() {
        let Some(at) = module.types.get_span(ty).to_range().and_then(|r| made_for.get(r.start).copied())
        else {
            return false;
        };
        makers.push(at);
    }
    // Before the first declaration: in every text alike.
    let made: Vec<usize> = makers.iter().flatten().copied().collect();
    let own = |d: &usize| member.declarations.contains_key(d);
    let counterparts = made
        .iter()
        .filter(|d| !own(d))
        .all(|d| member.counterparts.get(d).is_some_and(|stands_for| !made.contains(stands_for)));
    let mut foreign = made.iter().filter(|d| !own(d));
    let one = match (foreign.next(), foreign.next()) {
        (None, _) => true,
        (Some(&f), None) => made.iter().filter(|d| own(d)).all(|&d| d < f),
        _ => false,
    };
    counterparts || one || met_first_in_own_head(module, &makers, member, head_types)
}

/// Whether the types of `module` that other texts' declarations made (`makers`: the declaration
/// each type was made for, by the type's index) are numbered as the member's own text would
/// number them, because its first declaration after all of those makers meets them all in its
/// head, in that order, and none of its declarations after the first maker made a type it keeps.
fn met_first_in_own_head<'m>(
    module: &naga::Module,
    makers: &[Option<usize>],
    member: &Member,
    head_types: impl Fn(usize) -> Option<&'m [naga::TypeInner]>,
) -> bool {
    let own = |d: &usize| member.declarations.contains_key(d);
    let foreign_makers = || makers.iter().flatten().filter(|d| !own(d));
    let (Some(&first), Some(&last)) = (foreign_makers().min(), foreign_makers().max()) else { return true };
    // Alone, no declaration of its own before `first` met these types (it would have made them
    // there), nor between `first` and `next`: `next` meets them first.
    if makers.iter().flatten().any(|d| own(d) && *d > first) {
        return false;
    }
    let Some(&next) = member.declarations.keys().filter(|&&d| d > last).min() else { return false };
    if member.declarations.keys().any(|&d| d > first && d < next) {
        return false;
    }
    let foreign: Vec<&naga::TypeInner> = (module.types.iter().zip(makers))
        .filter(|(_, maker)| maker.is_some_and(|d| !own(&d)))
        .map(|((_, ty), _)| &ty.inner)
        .collect();
    // Types naming others by handle cannot be told apart across two modules.
    if !foreign.iter().all(|ty| handle_free(ty)) {
        return false;
    }
    head_types(next).is_some_and(|order| {
        let met: Vec<&naga::TypeInner> = order.iter().filter(|ty| foreign.contains(ty)).collect();
        met == foreign
    })
}

/// The types naga makes for a function's head alone, in the order it makes them.
fn head_order(head: &str) -> Option<Vec<naga::TypeInner>> {
    let module = contain_panics(|| naga::front::wgsl::parse_str(head).ok()).ok().flatten()?;
    Some(module.types.iter().map(|(_, ty)| ty.inner.clone()).collect())
}

/// Whether a type names no other type (so two modules' can be compared as they are).
fn handle_free(ty: &naga::TypeInner) -> bool {
    use naga::TypeInner as T;
    matches!(
        ty,
        T::Scalar(_)
            | T::Vector { .. }
            | T::Matrix { .. }
            | T::Atomic(_)
            | T::Image { .. }
            | T::Sampler { .. }
    )
}

/// Whether naga lowers the written declarations `a` and `b`, the same text naming other
/// declarations, alike: the same types met in the same order. So it does where each declaration
/// they name differently is a function whose head (parameters and result) is the same text naming
/// the same declarations.
fn lowered_alike(written: &[Written], a: usize, b: usize) -> bool {
    let (x, y) = (&written[a], &written[b]);
    if x.text != y.text || x.names.len() != y.names.len() {
        return false;
    }
    // What a function's head names, its own name aside.
    let head = |w: usize| -> Option<Vec<usize>> {
        let end = written[w].text.find('{')?;
        Some(written[w].names.iter().filter(|(r, t)| r.end <= end && *t != w).map(|(_, t)| *t).collect())
    };
    x.names.iter().zip(&y.names).all(|(&(_, p), &(_, q))| {
        let (f, g) = (&written[p], &written[q]);
        p == q
            || (p == a && q == b)
            || (f.kind == Kind::Function
                && g.kind == Kind::Function
                && f.text.split('{').next() == g.text.split('{').next()
                && head(p).is_some_and(|h| Some(h) == head(q)))
    })
}

/// The names written anew given back to what they name in a member's module.
fn give_names_back(module: &mut naga::Module, renamed: &[(String, String)]) {
    if renamed.is_empty() {
        return;
    }
    let original: HashMap<&str, &str> =
        renamed.iter().map(|(new, old)| (new.as_str(), old.as_str())).collect();
    let back = |name: &mut Option<String>| {
        if let Some(old) = name.as_deref().and_then(|n| original.get(n)) {
            *name = Some(old.to_string());
        }
    };
    for (_, function) in module.functions.iter_mut() {
        back(&mut function.name);
    }
    for (_, constant) in module.constants.iter_mut() {
        back(&mut constant.name);
    }
    for (_, r#override) in module.overrides.iter_mut() {
        back(&mut r#override.name);
    }
    for (_, global) in module.global_variables.iter_mut() {
        back(&mut global.name);
    }
    for entry in &mut module.entry_points {
        let mut name = Some(std::mem::take(&mut entry.name));
        back(&mut name);
        entry.name = name.unwrap_or_default();
        back(&mut entry.function.name);
    }
    let types: Vec<_> = module
        .types
        .iter()
        .filter(|(_, ty)| ty.name.as_deref().is_some_and(|n| original.contains_key(n)))
        .map(|(handle, ty)| (handle, ty.clone()))
        .collect();
    for (handle, mut ty) in types {
        back(&mut ty.name);
        module.types.replace(handle, ty);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `texts` to parse together, each with the entry point `entry`, scanned here.
    fn given<'t>(texts: &[&'t str], entry: &'t str) -> Vec<Text<'t>> {
        texts.iter().map(|text| Text { text, entry, scan: None }).collect()
    }

    /// What naga writes of a module: its WGSL and SPIR-V.
    fn written(module: &naga::Module) -> (String, Vec<u32>) {
        let flags = naga::valid::ValidationFlags::all() - naga::valid::ValidationFlags::BINDINGS;
        let info = naga::valid::Validator::new(flags, naga::valid::Capabilities::all())
            .validate(module)
            .expect("valid");
        let wgsl = naga::back::wgsl::write_string(module, &info, naga::back::wgsl::WriterFlags::empty())
            .expect("WGSL");
        let options = naga::back::spv::Options { fake_missing_bindings: true, ..Default::default() };
        let spirv = naga::back::spv::write_vec(module, &info, &options, None).expect("SPIR-V");
        (wgsl, spirv)
    }

    /// A text's own module: parsed alone, its entry point kept, compacted.
    fn alone(text: &str, entry: &str) -> naga::Module {
        let mut module = naga::front::wgsl::parse_str(text).expect("parses alone");
        module.entry_points.retain(|e| e.name == entry);
        naga::compact::compact(&mut module, naga::compact::KeepUnused::No);
        module
    }

    /// Parses `texts` (fragment stages of entry point `fs`) together and checks that every
    /// module cut out is what the text gives alone, byte for byte; which members were cut out.
    fn cut_out(texts: &[&str]) -> Vec<bool> {
        let jobs: Vec<(&str, &str)> = texts.iter().map(|&text| (text, "fs")).collect();
        stages_cut_out(&jobs, naga::ShaderStage::Fragment)
    }

    /// [`cut_out`] for `(text, entry point)` stages of `stage`.
    fn stages_cut_out(jobs: &[(&str, &str)], stage: naga::ShaderStage) -> Vec<bool> {
        let asked: Vec<Text> = jobs.iter().map(|&(text, entry)| Text { text, entry, scan: None }).collect();
        let Some(together) = assemble(&asked) else { return vec![false; jobs.len()] };
        let parsed = together.parse().unwrap_or_else(|| panic!("naga parses:\n{}", together.text));
        (0..jobs.len())
            .map(|i| match together.cut(&parsed, i, stage) {
                Some(module) => {
                    let (ours, theirs) = (written(&module), written(&alone(jobs[i].0, jobs[i].1)));
                    assert_eq!(ours.0, theirs.0, "member {i}'s WGSL, from:\n{}", together.text);
                    assert_eq!(ours.1, theirs.1, "member {i}'s SPIR-V, from:\n{}", together.text);
                    true
                }
                None => false,
            })
            .collect()
    }

    /// What a library declares first: the types variants use, made before any of their own
    /// declarations (naga numbers types as it meets them).
    const LIBRARY: &str = "const WHITE: vec4<f32> = vec4(1.0);\nconst UV: vec2<f32> = vec2(0.0);\n\
        struct Light { colour: vec3<f32>, direction: vec3<f32> }\n\
        @group(0) @binding(0) var<uniform> light: Light;\n\
        const AMBIENT: f32 = 0.1;\n\
        fn diffuse(n: vec3<f32>) -> vec3<f32> { return max(dot(n, light.direction), AMBIENT) * light.colour; }\n";

    #[test]
    fn variants_differing_in_their_entry_point_share_the_library_s_parse() {
        let a = format!(
            "{LIBRARY}@fragment fn fs() -> @location(0) vec4<f32> {{ return vec4(diffuse(vec3(0.0, 1.0, 0.0)), 1.0); }}\n"
        );
        let b = format!(
            "{LIBRARY}@fragment fn fs() -> @location(0) vec4<f32> {{ let c = diffuse(vec3(1.0, 0.0, 0.0)); return vec4(c * 2.0, 1.0); }}\n"
        );
        let c =
            format!("{LIBRARY}@fragment fn fs() -> @location(0) vec4<f32> {{ return vec4<f32>(1.0); }}\n");
        assert_eq!(cut_out(&[&a, &b, &c]), [true, true, true]);
        // Each library declaration is written once; each entry point under a name of its own.
        let together = assemble(&given(&[&a, &b, &c], "fs")).expect("together");
        assert_eq!(together.text.matches("fn diffuse").count(), 1);
        assert_eq!(together.text.matches("fn fs_kIlN").count(), 3);
    }

    #[test]
    fn what_calls_functions_of_one_head_is_written_once_and_each_member_keeps_its_own() {
        let text = |tint: &str, result: &str| {
            format!(
                "{LIBRARY}fn tint(c: vec3<f32>) -> {result} {{ {tint} }}\n\
                 fn lit(n: vec3<f32>) -> vec3<f32> {{ return tint(diffuse(n)).xyz; }}\n\
                 @fragment fn fs() -> @location(0) vec4<f32> {{ return vec4(lit(vec3(0.0, 1.0, 0.0)), 1.0); }}\n"
            )
        };
        let texts = [
            text("return c;", "vec3<f32>"),
            text("return c * 0.5;", "vec3<f32>"),
            // Its body is the first to meet `array<f32, 3>`: its own text meets it in its place.
            text("var k = array<f32, 3>(0.2, 0.7, 0.1); return c * k[1];", "vec3<f32>"),
            text("return c.zyx;", "vec3<f32>"),
            // Another head: what calls these is written again, once.
            text("return vec4(c, 1.0);", "vec4<f32>"),
            text("return vec4(c, 0.0);", "vec4<f32>"),
        ];
        let texts: Vec<&str> = texts.iter().map(String::as_str).collect();
        assert_eq!(cut_out(&texts), [true; 6]);
        let together = assemble(&given(&texts, "fs")).expect("together");
        assert_eq!(together.text.matches("fn tint").count(), 6, "{}", together.text);
        // `lit` once for the tints of each head; `fs` once, as both `lit`s have one head.
        assert_eq!(together.text.matches("fn lit").count(), 2, "{}", together.text);
        assert_eq!(together.text.matches("fn fs").count(), 1, "{}", together.text);
    }

    /// A variant of a small library: `shade`'s result and body, `tone`'s body, the entry point's
    /// extra term (indices into the tables below), and which of `tone` and `shade` comes first.
    fn variant(
        shade_result: usize,
        shade_body: usize,
        tone_body: usize,
        extra: usize,
        tone_first: bool,
    ) -> String {
        // Bodies that meet types nothing before them met (an array, a matrix, `vec2<u32>`, the
        // predeclared result of `modf`), use a constant, a global, or nothing.
        const BODIES: [&str; 7] = [
            "let r = v;",
            "var a = array<f32, 3>(1.0, 2.0, 3.0); let r = v * a[1];",
            "let m = mat2x2<f32>(); let r = v * m[0].x;",
            "let u = vec2<u32>(1u); let r = v * f32(u.x);",
            "let r = v * K;",
            "let f = modf(v.x); let r = v * f.fract;",
            "let r = vec4(g.xyz, 1.0);",
        ];
        const TONES: [&str; 3] = ["return x;", "return x * K;", "let i = vec3<i32>(2); return x * f32(i.y);"];
        let (result, returned, called) = match shade_result {
            0 => ("vec4<f32>", "r", "shade(v)"),
            _ => ("vec3<f32>", "r.xyz", "vec4(shade(v), 1.0)"),
        };
        let extra = ["", " + vec4(tone(2.0))"][extra];
        let tone = format!("fn tone(x: f32) -> f32 {{ {} }}\n", TONES[tone_body]);
        let shade =
            format!("fn shade(v: vec4<f32>) -> {result} {{ {} return {returned}; }}\n", BODIES[shade_body]);
        let (first, second) = if tone_first { (tone, shade) } else { (shade, tone) };
        format!(
            "const K: f32 = 0.5;\nvar<private> g: vec4<f32>;\n{first}{second}\
             fn lit(v: vec4<f32>) -> vec4<f32> {{ return {called} * tone(1.0); }}\n\
             @fragment fn fs() -> @location(0) vec4<f32> {{ return lit(vec4(0.5)){extra}; }}\n"
        )
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(96))]
        /// However variants differ in a function's body and head, each module cut out is naga's
        /// own parse of its text, byte for byte (`cut_out` asserts it), or left to that parse.
        #[test]
        fn every_module_cut_out_is_its_own_text_s(
            variants in proptest::collection::vec((0..2usize, 0..7usize, 0..3usize, 0..2usize, proptest::bool::ANY), 2..10)
        ) {
            let texts: Vec<String> = variants.iter().map(|&(r, b, t, e, o)| variant(r, b, t, e, o)).collect();
            let texts: Vec<&str> = texts.iter().map(String::as_str).collect();
            let cut = cut_out(&texts);
            // Variants whose `shade` meets no type of its own, in the first's order, share a parse.
            let plain = (variants.iter().zip(&texts))
                .filter(|((.., order), _)| *order == variants[0].4)
                .filter(|(_, t)| t.contains("let r = v;") || t.contains("let r = v * K;"))
                .count();
            proptest::prop_assert!(plain < 2 || cut.iter().filter(|&&c| c).count() >= 2, "{cut:?}");
        }
    }

    #[test]
    fn a_function_struct_or_constant_a_keyword_changes_is_written_once_per_meaning() {
        let normal = |body: &str| format!("fn normal() -> vec3<f32> {{ {body} }}\n");
        let text = |normal: &str, extra: &str, scale: &str| {
            format!(
                "{LIBRARY}struct Varyings {{ @location(0) uv: vec2<f32>, {extra} }}\nconst SCALE: f32 = {scale};\n{normal}\
                 fn shade(n: vec3<f32>) -> f32 {{ return n.y * SCALE; }}\n\
                 @fragment fn fs(v: Varyings) -> @location(0) vec4<f32> {{ return vec4(shade(normal()), v.uv, 1.0); }}\n"
            )
        };
        let a = text(&normal("return vec3(0.0, 1.0, 0.0);"), "", "1.0");
        let b = text(
            &normal("return normalize(vec3(0.5, 1.0, 0.0));"),
            "@location(1) tangent: vec4<f32>,",
            "1.0",
        );
        let c = text(&normal("return vec3(0.0, 1.0, 0.0);"), "", "2.0");
        assert_eq!(cut_out(&[&a, &b, &c]), [true, true, true]);
    }

    #[test]
    fn a_text_naming_what_only_another_declares_is_left_to_its_own_parse() {
        // Alone, `b` does not parse: together, `helper` would be found in `a`.
        let a = "fn helper() -> f32 { return 1.0; }\n@fragment fn fs() -> @location(0) vec4<f32> { return vec4(helper()); }\n";
        let b = "@fragment fn fs() -> @location(0) vec4<f32> { return vec4(helper()); }\n";
        let c = "@fragment fn fs() -> @location(0) vec4<f32> { return vec4(2.0); }\n";
        assert_eq!(cut_out(&[a, b, c]), [true, false, true]);
        // A built-in one text shadows is another text's built-in.
        let d = "fn min(a: f32, b: f32) -> f32 { return a; }\n@fragment fn fs() -> @location(0) vec4<f32> { return vec4(min(1.0, 2.0)); }\n";
        let e = "@fragment fn fs() -> @location(0) vec4<f32> { return vec4(min(1.0, 2.0)); }\n";
        assert_eq!(cut_out(&[d, e]), [false, false]);
    }

    #[test]
    fn a_local_named_as_a_name_written_anew_leaves_its_text_alone() {
        // `scale` is written anew (two meanings); `b`'s parameter of that name must keep its own.
        let a = &format!(
            "{LIBRARY}{}",
            "const scale: f32 = 1.0;\nfn f(x: f32) -> f32 { return x * scale; }\n@fragment fn fs() -> @location(0) vec4<f32> { return vec4(f(1.0)); }\n"
        );
        let b = &format!(
            "{LIBRARY}{}",
            "const scale: f32 = 2.0;\nfn f(scale: f32) -> f32 { return scale; }\n@fragment fn fs() -> @location(0) vec4<f32> { return vec4(f(1.0)); }\n"
        );
        let c = &format!(
            "{LIBRARY}{}",
            "const scale: f32 = 3.0;\nfn f(x: f32) -> f32 { return x * scale; }\n@fragment fn fs() -> @location(0) vec4<f32> { return vec4(f(1.0)); }\n"
        );
        assert_eq!(cut_out(&[a, b, c]), [true, false, true]);
    }

    #[test]
    fn a_type_first_made_for_another_text_leaves_a_member_alone_or_the_same() {
        // `b` meets `mat3x3<f32>` first in its own entry point, which `a`'s comes before: were it
        // cut out, its types would be numbered in another order than alone.
        let a = "const WHITE: vec4<f32> = vec4(1.0);\n@fragment fn fs() -> @location(0) vec4<f32> { let m = mat3x3<f32>(); let v = vec2<u32>(); return vec4(m[0], f32(v.x)); }\n";
        let b = "const WHITE: vec4<f32> = vec4(1.0);\n@fragment fn fs() -> @location(0) vec4<f32> { let v = vec2<u32>(); let m = mat3x3<f32>(); return vec4(m[0], f32(v.x)); }\n";
        let c = "const WHITE: vec4<f32> = vec4(1.0);\n@fragment fn fs() -> @location(0) vec4<f32> { let f = modf(1.5); return vec4(f.fract); }\n";
        let d = "const WHITE: vec4<f32> = vec4(1.0);\n@fragment fn fs() -> @location(0) vec4<f32> { return WHITE; }\n";
        let cut = cut_out(&[a, b, c, d]);
        assert_eq!((cut[0], cut[1], cut[3]), (true, false, true));
    }

    #[test]
    fn an_entry_point_lowered_alike_takes_the_types_its_counterpart_made_first() {
        // Each variant's entry point is the same text calling its own `shape`, and is the first
        // to meet `u32` and `vec3<u32>`: in the text parsed together, the first variant's makes
        // them, as each variant's own would alone.
        let text = |body: &str, result: &str| {
            format!(
                "var<storage, read_write> data: array<vec4<f32>>;\n\
                 fn shape(v: vec4<f32>) -> {result} {{ {body} }}\n\
                 @compute @workgroup_size(64) fn main(@builtin(global_invocation_id) id: vec3<u32>) {{\n\
                 let v = data[id.x];\n data[id.x] = v + vec4<f32>(shape(v)) * 0.016;\n}}\n"
            )
        };
        let texts = [
            text("return v * 1.01;", "vec4<f32>"),
            text("return sin(v);", "vec4<f32>"),
            text("return mix(v, cos(v), 0.2);", "vec4<f32>"),
            // A `shape` of another result: its entry point is not lowered alike (cut out or not,
            // its module is what it is alone).
            text("return vec4<u32>(v);", "vec4<u32>"),
        ];
        let texts: Vec<&str> = texts.iter().map(String::as_str).collect();
        let asked = given(&texts, "main");
        let together = assemble(&asked).expect("together");
        // The three entry points calling a `shape` of one head are written once.
        assert_eq!(together.text.matches("fn main").count(), 2, "{}", together.text);
        let parsed = together.parse().expect("parses");
        let cut: Vec<bool> = (0..texts.len())
            .map(|i| match together.cut(&parsed, i, naga::ShaderStage::Compute) {
                Some(module) => {
                    assert_eq!(written(&module), written(&alone(texts[i], "main")), "member {i}");
                    true
                }
                None => false,
            })
            .collect();
        assert_eq!(cut[..3], [true, true, true]);
    }

    #[test]
    fn a_variant_s_kernels_share_a_parse_where_their_heads_number_types_alike() {
        // Each kernel's text is cut to what it reaches. `integrate` is written before `reduce`
        // and makes `u32` and `vec3<u32>` first; `reduce`'s head meets them in that order too.
        let kernel = |shape: &str, entry: &str| {
            let head = match entry {
                "integrate" => "integrate(@builtin(global_invocation_id) id: vec3<u32>) { let n = id.x;",
                _ => "reduce(@builtin(local_invocation_index) n: u32, @builtin(workgroup_id) g: vec3<u32>) {",
            };
            format!(
                "var<storage, read_write> data: array<vec4<f32>>;\n\
                 fn shape(v: vec4<f32>) -> vec4<f32> {{ {shape} }}\n\
                 @compute @workgroup_size(64) fn {head} data[n] = shape(data[n]); }}\n"
            )
        };
        let texts: Vec<(String, &str)> =
            ["return v * 1.01;", "return sin(v);", "return mix(v, cos(v), 0.2);"]
                .iter()
                .flat_map(|shape| ["integrate", "reduce"].map(|entry| (kernel(shape, entry), entry)))
                .collect();
        let jobs: Vec<(&str, &str)> = texts.iter().map(|(text, entry)| (text.as_str(), *entry)).collect();
        assert_eq!(stages_cut_out(&jobs, naga::ShaderStage::Compute), [true; 6]);
        // Helpers whose heads meet another text's types in another order are left alone; in the
        // same order, they are cut out.
        let helper = |name: &str, parameters: &str, arguments: &str| {
            format!(
                "fn {name}({parameters}) -> f32 {{ return a.x + f32(b.y); }}\n\
                 @compute @workgroup_size(1) fn main_{name}() {{ _ = {name}({arguments}); }}\n"
            )
        };
        let first = helper("p", "a: vec2<f32>, b: vec3<i32>", "vec2(1.0), vec3(2)");
        let swapped = helper("q", "b: vec3<i32>, a: vec2<f32>", "vec3(2), vec2(1.0)");
        let same = helper("r", "a: vec2<f32>, b: vec3<i32>", "vec2(1.0), vec3(2)");
        let jobs = [(first.as_str(), "main_p"), (swapped.as_str(), "main_q"), (same.as_str(), "main_r")];
        assert_eq!(stages_cut_out(&jobs, naga::ShaderStage::Compute), [true, false, true]);
    }

    #[test]
    fn texts_with_other_directives_or_markers_are_left_alone() {
        let a = "enable f16;\n@fragment fn fs() -> @location(0) vec4<f32> { return vec4(f32(1.0h)); }\n";
        let b =
            &format!("{LIBRARY}{}", "@fragment fn fs() -> @location(0) vec4<f32> { return vec4(1.0); }\n");
        let c =
            &format!("{LIBRARY}{}", "@fragment fn fs() -> @location(0) vec4<f32> { return vec4(2.0); }\n");
        assert_eq!(cut_out(&[a, b, c]), [false, true, true]);
        let d =
            "fn kIlN_m0() {}\n@fragment fn fs() -> @location(0) vec4<f32> { kIlN_m0(); return vec4(2.0); }\n";
        assert_eq!(cut_out(&[b, d]), [false, false]);
    }
}

//! The syntax of `scene!`, read with `syn`.
//!
//! Parsing only checks the shape of the input: a sequence of `VIS mod NAME { KEY: VALUE, ... }`
//! items whose keys are known and whose values have the right token form for their key. Anything
//! that needs the IR file or compares entries with each other (duplicate keys, unknown
//! parameters, the numeric value of a fixed parameter) is left to [`crate::validate`], so that
//! all such problems can be reported together.

use syn::ext::IdentExt;
use syn::parse::{Parse, ParseStream};
use syn::punctuated::Punctuated;
use syn::{braced, bracketed, Attribute, Expr, Ident, LitInt, LitStr, Token, Visibility};

/// The whole macro input: one or more scene declarations.
pub struct SceneInput {
    /// The scenes, in source order.
    pub scenes: Vec<SceneDecl>,
}

/// One `VIS mod NAME { ... }` scene declaration, as written.
pub struct SceneDecl {
    /// Outer attributes (doc comments included), passed through to the module.
    pub attrs: Vec<Attribute>,
    /// The module's visibility.
    pub vis: Visibility,
    /// The module's name.
    pub name: Ident,
    /// The `KEY: VALUE` entries, in source order, duplicates included.
    pub entries: Vec<Entry>,
}

/// One `KEY: VALUE` entry of a scene.
pub struct Entry {
    /// The key as written, for error spans.
    pub key: Ident,
    /// The value, whose form depends on the key.
    pub value: EntryValue,
}

/// The value of an entry, by key.
pub enum EntryValue {
    /// `model: NAME`.
    Model(Ident),
    /// `path: "FILE"`.
    Path(LitStr),
    /// `fixed: { NAME: VALUE, ... }`.
    Fixed(Vec<FixedEntry>),
    /// `outputs: [NAME, ...]`.
    Outputs(Vec<Ident>),
    /// `max_fn_ops: N`.
    MaxFnOps(LitInt),
    /// `lanes: N`.
    Lanes(LitInt),
    /// `jacobian: [NAME, ...]`.
    Jacobian(Vec<Ident>),
    /// `newton: { input: NAME, residual: NAME, derivative: NAME }`.
    Newton(Newton),
}

/// The value of `newton`: one Newton step on `input` for the root of the output `residual`,
/// whose derivative with respect to `input` is the output `derivative`.
pub struct Newton {
    /// The input stepped.
    pub input: Ident,
    /// The output whose root is sought.
    pub residual: Ident,
    /// The output that is its derivative with respect to the input.
    pub derivative: Ident,
}

/// One `NAME: VALUE` pair of `fixed`; the value is any expression here and must turn out to be
/// a (possibly negated) numeric literal in validation.
pub struct FixedEntry {
    /// The parameter name.
    pub name: Ident,
    /// The value as written.
    pub value: Expr,
}

/// The keys a scene accepts, for error messages.
pub const KEYS: &str =
    "`model`, `path`, `fixed`, `outputs`, `max_fn_ops`, `lanes`, `jacobian`, `newton`";

impl Parse for SceneInput {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let mut scenes = Vec::new();
        while !input.is_empty() {
            scenes.push(input.parse()?);
        }
        if scenes.is_empty() {
            return Err(
                input.error("expected at least one scene: `pub mod NAME { model: MODEL, ... }`")
            );
        }
        Ok(SceneInput { scenes })
    }
}

impl Parse for SceneDecl {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let attrs = input.call(Attribute::parse_outer)?;
        let vis: Visibility = input.parse()?;
        input.parse::<Token![mod]>()?;
        let name: Ident = input.parse()?;
        let content;
        braced!(content in input);
        let entries = Punctuated::<Entry, Token![,]>::parse_terminated(&content)?;
        Ok(SceneDecl { attrs, vis, name, entries: entries.into_iter().collect() })
    }
}

impl Parse for Entry {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let key = Ident::parse_any(input)?;
        input.parse::<Token![:]>()?;
        let value = match key.to_string().as_str() {
            "model" => EntryValue::Model(Ident::parse_any(input)?),
            "path" => EntryValue::Path(input.parse()?),
            "fixed" => {
                let content;
                braced!(content in input);
                let items = Punctuated::<FixedEntry, Token![,]>::parse_terminated(&content)?;
                EntryValue::Fixed(items.into_iter().collect())
            }
            "outputs" => EntryValue::Outputs(names(input)?),
            "jacobian" => EntryValue::Jacobian(names(input)?),
            "max_fn_ops" => EntryValue::MaxFnOps(input.parse()?),
            "lanes" => EntryValue::Lanes(input.parse()?),
            "newton" => EntryValue::Newton(input.parse()?),
            other => {
                return Err(syn::Error::new_spanned(
                    &key,
                    format!("unknown scene key `{other}`; expected one of {KEYS}"),
                ))
            }
        };
        Ok(Entry { key, value })
    }
}

/// `[NAME, ...]`: a bracketed list of names (keywords allowed).
fn names(input: ParseStream) -> syn::Result<Vec<Ident>> {
    let content;
    bracketed!(content in input);
    let items = Punctuated::<Ident, Token![,]>::parse_terminated_with(&content, Ident::parse_any)?;
    Ok(items.into_iter().collect())
}

impl Parse for Newton {
    /// `{ input: NAME, residual: NAME, derivative: NAME }`, in this order (names may be
    /// keywords), with an optional trailing comma.
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let content;
        braced!(content in input);
        let field = |want: &str, first: bool| -> syn::Result<Ident> {
            if !first {
                content.parse::<Token![,]>()?;
            }
            let key = Ident::parse_any(&content)?;
            if key != want {
                return Err(syn::Error::new_spanned(
                    &key,
                    format!(
                        "expected `{want}` in `newton: {{ input: NAME, residual: NAME, \
                         derivative: NAME }}`, found `{key}`"
                    ),
                ));
            }
            content.parse::<Token![:]>()?;
            Ident::parse_any(&content)
        };
        let input = field("input", true)?;
        let residual = field("residual", false)?;
        let derivative = field("derivative", false)?;
        if content.peek(Token![,]) {
            content.parse::<Token![,]>()?;
        }
        if !content.is_empty() {
            return Err(content.error("unexpected tokens after `derivative` in `newton`"));
        }
        Ok(Newton { input, residual, derivative })
    }
}

impl Parse for FixedEntry {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let name = Ident::parse_any(input)?;
        input.parse::<Token![:]>()?;
        let value: Expr = input.parse()?;
        Ok(FixedEntry { name, value })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use quote::quote;

    fn parse(ts: proc_macro2::TokenStream) -> syn::Result<SceneInput> {
        syn::parse2(ts)
    }

    #[test]
    fn full_syntax_with_two_scenes() {
        let input = parse(quote! {
            /// Docs.
            pub mod a {
                model: demo,
                path: "fixtures/demo.ir",
                fixed: { R: 0.5, g: -9.81, },
                outputs: [poly, r#type],
                max_fn_ops: 4,
            }
            mod b { model: demo }
        })
        .unwrap();
        assert_eq!(input.scenes.len(), 2);
        let a = &input.scenes[0];
        assert_eq!(a.name, "a");
        assert_eq!(a.attrs.len(), 1);
        let keys: Vec<String> = a.entries.iter().map(|e| e.key.to_string()).collect();
        assert_eq!(keys, ["model", "path", "fixed", "outputs", "max_fn_ops"]);
        match &a.entries[2].value {
            EntryValue::Fixed(f) => {
                assert_eq!(f.len(), 2);
                assert_eq!(f[1].name, "g");
                assert!(matches!(f[1].value, Expr::Unary(_)));
            }
            _ => panic!("fixed parsed as another key"),
        }
        match &a.entries[3].value {
            EntryValue::Outputs(o) => assert_eq!(o[1].unraw(), "type"),
            _ => panic!("outputs parsed as another key"),
        }
        assert!(matches!(input.scenes[1].vis, Visibility::Inherited));
    }

    #[test]
    fn duplicate_keys_are_left_to_validation() {
        let input = parse(quote!(mod a { model: x, model: y })).unwrap();
        assert_eq!(input.scenes[0].entries.len(), 2);
    }

    #[test]
    fn malformed_inputs_are_errors() {
        let cases = [
            (quote!(), "expected at least one scene"),
            (
                quote!(
                    pub struct A;
                ),
                "expected `mod`",
            ),
            (quote!(mod a { colour: red }), "unknown scene key `colour`"),
            (quote!(mod a { model hoop }), "expected `:`"),
            (quote!(mod a { model: "hoop" }), "expected ident"),
            (quote!(mod a { path: hoop }), "expected string literal"),
            (quote!(mod a { outputs: { x } }), "expected square brackets"),
            (quote!(mod a { fixed: [R: 1.0] }), "expected curly braces"),
            (quote!(mod a { model: hoop } junk), "expected `mod`"),
            (
                quote!(mod a { newton: { residual: h, input: x, derivative: d } }),
                "expected `input` in `newton",
            ),
            (quote!(mod a { newton: { input: x, residual: h } }), "expected `,`"),
            (
                quote!(mod a { newton: { input: x, residual: h, derivative: d, more: y } }),
                "unexpected tokens after `derivative`",
            ),
        ];
        for (ts, want) in cases {
            let text = ts.to_string();
            let err = parse(ts).err().unwrap_or_else(|| panic!("`{text}` parsed"));
            assert!(
                err.to_string().contains(want),
                "`{text}`: error `{err}` does not contain `{want}`"
            );
        }
    }
}

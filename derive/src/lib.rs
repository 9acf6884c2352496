//! `#[derive(ParamSet)]`: the parameter schema of a scene's parameter struct,
//! written once per field.
//!
//! Each field carries its meaning (the first paragraph of its doc comment)
//! and a `#[param(...)]` attribute with its label, unit, range and default.
//! The derive generates, in the `grainscope` crate's terms:
//!
//! - `impl Default`, from each field's `default = …` (a field without one
//!   takes its type's default);
//! - `impl crate::scene::schema::ParamSet`: the controls bound to the fields
//!   (what the window and `--set` edit), a typed `get` of one value by key
//!   that reads the field directly, and the static list of parameter specs
//!   (key, label, units, range, default, meaning).
//!
//! Field attributes:
//!
//! | attribute | meaning |
//! | --- | --- |
//! | `label = "…"` | the label in the window |
//! | `key = "…"` | the key in presets and on the command line (default: the field's name) |
//! | `unit = "…"` | the SI unit of the stored value |
//! | `shown("µm", 1e6)` | the unit shown in the window and the factor from SI to it |
//! | `range(lo, hi)` | the valid range (SI; whole numbers for counts) |
//! | `log` | a logarithmic slider |
//! | `default = expr` | the default value |
//! | `style_only` | changing it restyles the output; nothing is recomputed |
//! | `figure_only` | it sets only what a figure shows (an axis range, a curve's resolution, an overlay): no scalar depends on it (the audit holds it to that) |
//! | `numerical` | it sets a numerical resolution or sample of the method (a count, a step, a tolerance, a seed), not the physics: a converged answer does not depend on it, and sensitivity tools report it apart |
//! | `choices = expr` | a `String` field that holds one of these (key, label) options |
//! | `quantity = path` | a shared quantity: `path(&mut field)` gives the control; `label`, `doc` and the rest refine it |
//! | `below = field` | the value must be below that of the sibling field `field` (a range's two ends) |
//! | `flatten` | the field is itself a parameter struct whose parameters are listed here |
//! | `except("a", …)` | with `flatten`: leave out these keys |
//! | `skip` | not a parameter (it still takes `default`) |
//! | `doc = "…"` | the meaning, when it should differ from the doc comment |
//!
//! Struct attribute `#[param(manual_default)]`: the struct writes its own
//! `Default` (for defaults derived from one another).
//!
//! `#[derive(Choice)]` on an enum of unit variants, each with
//! `#[choice(key = "…", label = "…")]`: a parameter that is one of fixed
//! options. It is stored in files by its key (serde, as text), listed with
//! its labels, and compared as a value in code.

use proc_macro::TokenStream;
use proc_macro2::TokenStream as Tokens;
use quote::quote;
use syn::punctuated::Punctuated;
use syn::{Data, DeriveInput, Expr, Fields, LitStr, Path, Token, parse_macro_input};

/// Derives `Default` and `crate::scene::schema::ParamSet` from the fields'
/// `#[param(...)]` attributes and doc comments (see the crate documentation).
#[proc_macro_derive(ParamSet, attributes(param))]
pub fn derive_param_set(input: TokenStream) -> TokenStream {
    let input = parse_macro_input!(input as DeriveInput);
    match expand(&input) {
        Ok(tokens) => tokens.into(),
        Err(e) => e.to_compile_error().into(),
    }
}

/// What one field's attribute says.
#[derive(Default)]
struct FieldSpec {
    key: Option<LitStr>,
    label: Option<LitStr>,
    unit: Option<LitStr>,
    shown: Option<(Expr, Expr)>,
    range: Option<(Expr, Expr)>,
    log: bool,
    default: Option<Expr>,
    style_only: bool,
    figure_only: bool,
    numerical: bool,
    below: Option<syn::Ident>,
    choices: Option<Expr>,
    quantity: Option<Path>,
    flatten: bool,
    except: Vec<LitStr>,
    skip: bool,
    doc: Option<LitStr>,
}

fn two_exprs(content: syn::parse::ParseStream) -> syn::Result<(Expr, Expr)> {
    let list = Punctuated::<Expr, Token![,]>::parse_terminated(content)?;
    let mut it = list.into_iter();
    match (it.next(), it.next(), it.next()) {
        (Some(a), Some(b), None) => Ok((a, b)),
        _ => Err(content.error("expected two values")),
    }
}

fn field_spec(field: &syn::Field) -> syn::Result<FieldSpec> {
    let mut spec = FieldSpec::default();
    for attr in field.attrs.iter().filter(|a| a.path().is_ident("param")) {
        attr.parse_nested_meta(|meta| {
            let p = &meta.path;
            if p.is_ident("key") {
                spec.key = Some(meta.value()?.parse()?);
            } else if p.is_ident("label") {
                spec.label = Some(meta.value()?.parse()?);
            } else if p.is_ident("unit") {
                spec.unit = Some(meta.value()?.parse()?);
            } else if p.is_ident("shown") {
                let content;
                syn::parenthesized!(content in meta.input);
                spec.shown = Some(two_exprs(&content)?);
            } else if p.is_ident("range") {
                let content;
                syn::parenthesized!(content in meta.input);
                spec.range = Some(two_exprs(&content)?);
            } else if p.is_ident("log") {
                spec.log = true;
            } else if p.is_ident("default") {
                spec.default = Some(meta.value()?.parse()?);
            } else if p.is_ident("style_only") {
                spec.style_only = true;
            } else if p.is_ident("figure_only") {
                spec.figure_only = true;
            } else if p.is_ident("numerical") {
                spec.numerical = true;
            } else if p.is_ident("below") {
                spec.below = Some(meta.value()?.parse()?);
            } else if p.is_ident("choices") {
                spec.choices = Some(meta.value()?.parse()?);
            } else if p.is_ident("quantity") {
                spec.quantity = Some(meta.value()?.parse()?);
            } else if p.is_ident("flatten") {
                spec.flatten = true;
            } else if p.is_ident("except") {
                let content;
                syn::parenthesized!(content in meta.input);
                spec.except = Punctuated::<LitStr, Token![,]>::parse_terminated(&content)?.into_iter().collect();
            } else if p.is_ident("skip") {
                spec.skip = true;
            } else if p.is_ident("doc") {
                spec.doc = Some(meta.value()?.parse()?);
            } else {
                return Err(meta.error("unknown parameter attribute"));
            }
            Ok(())
        })?;
    }
    Ok(spec)
}

/// The first paragraph of the doc comment, as one line.
fn doc_paragraph(attrs: &[syn::Attribute]) -> Option<String> {
    let mut lines = Vec::new();
    for attr in attrs.iter().filter(|a| a.path().is_ident("doc")) {
        if let syn::Meta::NameValue(nv) = &attr.meta
            && let Expr::Lit(syn::ExprLit { lit: syn::Lit::Str(s), .. }) = &nv.value
        {
            let line = s.value();
            let line = line.trim();
            if line.is_empty() {
                if lines.is_empty() {
                    continue;
                }
                break;
            }
            lines.push(line.to_string());
        }
    }
    (!lines.is_empty()).then(|| lines.join(" "))
}

fn manual_default(input: &DeriveInput) -> syn::Result<bool> {
    let mut manual = false;
    for attr in input.attrs.iter().filter(|a| a.path().is_ident("param")) {
        attr.parse_nested_meta(|meta| {
            if meta.path.is_ident("manual_default") {
                manual = true;
                Ok(())
            } else {
                Err(meta.error("unknown struct attribute (expected manual_default)"))
            }
        })?;
    }
    Ok(manual)
}

fn expand(input: &DeriveInput) -> syn::Result<Tokens> {
    let name = &input.ident;
    let Data::Struct(data) = &input.data else {
        return Err(syn::Error::new_spanned(input, "ParamSet is derived for structs with named fields"));
    };
    let Fields::Named(fields) = &data.fields else {
        return Err(syn::Error::new_spanned(input, "ParamSet is derived for structs with named fields"));
    };
    let schema = quote!(crate::scene::schema);
    let mut controls = Vec::new();
    let mut getters = Vec::new();
    let mut checks = Vec::new();
    let mut defaults = Vec::new();
    for field in &fields.named {
        let ident = field.ident.as_ref().ok_or_else(|| syn::Error::new_spanned(field, "unnamed field"))?;
        let spec = field_spec(field)?;
        let default = match &spec.default {
            Some(e) => quote!(#e),
            None => quote!(::core::default::Default::default()),
        };
        defaults.push(quote!(#ident: #default));
        if spec.skip {
            continue;
        }
        if spec.flatten {
            let except = &spec.except;
            controls.push(quote! {
                c.extend(
                    #schema::ParamSet::controls_with(&mut self.#ident, &d.#ident)
                        .into_iter()
                        .filter(|c| ![#(#except),*].contains(&c.key)),
                );
            });
            checks.push(quote!(#schema::ParamSet::check_all(&self.#ident)?;));
            getters.push(quote! {
                if ![#(#except),*].contains(&key) {
                    if let ::core::option::Option::Some(v) = #schema::ParamSet::get(&self.#ident, key) {
                        return ::core::option::Option::Some(v);
                    }
                }
            });
            continue;
        }
        let key = spec.key.clone().unwrap_or_else(|| LitStr::new(&ident.to_string(), ident.span()));
        let doc = spec.doc.as_ref().map(LitStr::value).or_else(|| doc_paragraph(&field.attrs));
        let mut chain = if let Some(q) = &spec.quantity {
            let mut t = quote!(#q(&mut self.#ident));
            if let Some(l) = &spec.label {
                t = quote!(#t.labelled(#l));
            }
            t
        } else {
            let label =
                spec.label.as_ref().ok_or_else(|| syn::Error::new_spanned(ident, "a parameter needs `label`"))?;
            match &spec.choices {
                Some(options) => quote!(#schema::Control::choice(#key, #label, &mut self.#ident, (#options).to_vec())),
                None => quote!(#schema::FieldControl::control(#key, #label, &mut self.#ident)),
            }
        };
        if let Some(u) = &spec.unit {
            chain = quote!(#chain.unit(#u));
        }
        if let Some((u, s)) = &spec.shown {
            chain = quote!(#chain.shown(#u, #s));
        }
        if let Some((lo, hi)) = &spec.range {
            chain = quote!(#chain.range((#lo) as f64, (#hi) as f64));
        }
        if spec.log {
            chain = quote!(#chain.log());
        }
        chain = quote!(#chain.default(#schema::FieldValue::value(&d.#ident)));
        if spec.style_only {
            chain = quote!(#chain.style_only());
        }
        if spec.figure_only {
            chain = quote!(#chain.figure_only());
        }
        if spec.numerical {
            chain = quote!(#chain.numerical());
        }
        match doc {
            Some(doc) => chain = quote!(#chain.doc(#doc)),
            None if spec.quantity.is_none() => {
                return Err(syn::Error::new_spanned(ident, "a parameter needs a doc comment or `doc`"));
            }
            None => {}
        }
        controls.push(quote!(c.push(#chain);));
        checks.push(quote! {
            if let ::core::option::Option::Some(spec) = <Self as #schema::ParamSet>::spec(#key) {
                #schema::FieldValue::check(&self.#ident, spec)?;
            }
        });
        if let Some(other) = &spec.below {
            let other_key = LitStr::new(&other.to_string(), other.span());
            checks.push(quote! {
                if !(self.#ident < self.#other) {
                    return ::core::result::Result::Err(#schema::ParamError::Inconsistent(::std::format!(
                        "{} = {} must be below {} = {}",
                        #key,
                        #schema::short(self.#ident as f64),
                        #other_key,
                        #schema::short(self.#other as f64)
                    )));
                }
            });
        }
        getters.push(quote! {
            if key == #key {
                return ::core::option::Option::Some(#schema::FieldValue::value(&self.#ident));
            }
        });
    }
    let default_impl = if manual_default(input)? {
        quote!()
    } else {
        quote! {
            impl ::core::default::Default for #name {
                fn default() -> Self {
                    #name { #(#defaults),* }
                }
            }
        }
    };
    let lifetime = syn::Lifetime::new("'a", proc_macro2::Span::call_site());
    Ok(quote! {
        #default_impl

        impl #schema::ParamSet for #name {
            fn controls_with<#lifetime>(&#lifetime mut self, d: &Self) -> ::std::vec::Vec<#schema::Control<#lifetime>> {
                let mut c = ::std::vec::Vec::new();
                #(#controls)*
                c
            }

            fn get(&self, key: &str) -> ::core::option::Option<#schema::Value> {
                #(#getters)*
                ::core::option::Option::None
            }

            fn check_all(&self) -> ::core::result::Result<(), #schema::ParamError> {
                #(#checks)*
                ::core::result::Result::Ok(())
            }

            fn specs() -> &'static [#schema::Spec] {
                static SPECS: ::std::sync::LazyLock<::std::vec::Vec<#schema::Spec>> =
                    ::std::sync::LazyLock::new(#schema::specs_of::<#name>);
                &SPECS
            }
        }
    })
}

/// Derives `crate::scene::schema::Choice`, text (de)serialisation by key and
/// the field traits for an enum of options (see the crate documentation).
#[proc_macro_derive(Choice, attributes(choice))]
pub fn derive_choice(input: TokenStream) -> TokenStream {
    let input = parse_macro_input!(input as DeriveInput);
    match expand_choice(&input) {
        Ok(tokens) => tokens.into(),
        Err(e) => e.to_compile_error().into(),
    }
}

fn expand_choice(input: &DeriveInput) -> syn::Result<Tokens> {
    let name = &input.ident;
    let Data::Enum(data) = &input.data else {
        return Err(syn::Error::new_spanned(input, "Choice is derived for enums of unit variants"));
    };
    let schema = quote!(crate::scene::schema);
    let mut variants = Vec::new();
    let mut options = Vec::new();
    for v in &data.variants {
        if !matches!(v.fields, Fields::Unit) {
            return Err(syn::Error::new_spanned(v, "an option is a unit variant"));
        }
        let (mut key, mut label) = (None::<LitStr>, None::<LitStr>);
        for attr in v.attrs.iter().filter(|a| a.path().is_ident("choice")) {
            attr.parse_nested_meta(|meta| {
                if meta.path.is_ident("key") {
                    key = Some(meta.value()?.parse()?);
                } else if meta.path.is_ident("label") {
                    label = Some(meta.value()?.parse()?);
                } else {
                    return Err(meta.error("expected key or label"));
                }
                Ok(())
            })?;
        }
        let key = key.ok_or_else(|| syn::Error::new_spanned(v, "an option needs `key`"))?;
        let label = label.ok_or_else(|| syn::Error::new_spanned(v, "an option needs `label`"))?;
        variants.push((v.ident.clone(), key.clone()));
        options.push(quote!((#key, #label)));
    }
    let to_key = variants.iter().map(|(v, k)| quote!(#name::#v => #k));
    let from_key = variants.iter().map(|(v, k)| quote!(#k => ::core::option::Option::Some(#name::#v)));
    Ok(quote! {
        impl #schema::Choice for #name {
            const OPTIONS: &'static [(&'static str, &'static str)] = &[#(#options),*];

            fn key(&self) -> &'static str {
                match self {
                    #(#to_key,)*
                }
            }

            fn from_key(key: &str) -> ::core::option::Option<Self> {
                match key {
                    #(#from_key,)*
                    _ => ::core::option::Option::None,
                }
            }
        }

        impl ::serde::Serialize for #name {
            fn serialize<S: ::serde::Serializer>(&self, serializer: S) -> ::core::result::Result<S::Ok, S::Error> {
                serializer.serialize_str(#schema::Choice::key(self))
            }
        }

        impl<'de> ::serde::Deserialize<'de> for #name {
            fn deserialize<D: ::serde::Deserializer<'de>>(deserializer: D) -> ::core::result::Result<Self, D::Error> {
                let text = <::std::string::String as ::serde::Deserialize>::deserialize(deserializer)?;
                <#name as #schema::Choice>::from_key(&text).ok_or_else(|| {
                    <D::Error as ::serde::de::Error>::custom(#schema::unknown_option(&text, <#name as #schema::Choice>::OPTIONS))
                })
            }
        }

        impl #schema::FieldValue for #name {
            fn value(&self) -> #schema::Value {
                #schema::Value::Text(#schema::Choice::key(self).to_string())
            }
        }

        impl #schema::FieldControl for #name {
            fn control<'a>(key: &'static str, label: &'static str, value: &'a mut Self) -> #schema::Control<'a> {
                #schema::Control::choice(key, label, value, <#name as #schema::Choice>::OPTIONS.to_vec())
            }
        }
    })
}

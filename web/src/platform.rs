//! The browser platform: the page's file picker for opening, downloads for
//! saving, `localStorage` for the session, and the page's clock. A browser
//! has no paths: a name the user types is the name of the download, and
//! reading a typed name is refused with a hint to open the file instead.

use grainscope::app::platform::{Answer, FileKind, Picked, Platform, SharedLink};
use grainscope::session::Restored;
use std::cell::RefCell;
use std::rc::Rc;
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;

/// Key of the session in the page's storage.
const SESSION_KEY: &str = "grainscope-session";
/// Key under which an unreadable session is set aside.
const UNREADABLE_KEY: &str = "grainscope-session-unreadable";
/// The largest session kept in the page's storage, bytes (browsers allow
/// about 5 MB per site; pins and histories can grow a session past that).
pub const SESSION_LIMIT: usize = 1_000_000;

/// Files, dialogs, session and clock of a browser tab.
pub struct WebPlatform {
    /// Answers of file pickers and downloads, filled by the page's events.
    answers: Rc<RefCell<Vec<Answer>>>,
    /// Whether the page's storage may be written.
    may_save: bool,
    /// Asks for a frame: an answer that arrives between frames is seen at once.
    wake: Rc<dyn Fn()>,
}

impl WebPlatform {
    /// The platform of the current page; `wake` asks the page for a frame.
    pub fn new(wake: impl Fn() + 'static) -> Self {
        WebPlatform { answers: Rc::default(), may_save: true, wake: Rc::new(wake) }
    }

    /// The queue its answers go to: files dropped on the page join it.
    pub fn answers(&self) -> Rc<RefCell<Vec<Answer>>> {
        Rc::clone(&self.answers)
    }
}

/// The kind of a file the user dropped, by its name.
pub fn kind_of(name: &str) -> FileKind {
    match name.rsplit('.').next().map(str::to_ascii_lowercase).as_deref() {
        Some("ron") => FileKind::Preset,
        Some("csv") => FileKind::Measurements,
        _ => FileKind::Figure,
    }
}

/// The page's storage, if the browser allows it.
fn storage() -> Option<web_sys::Storage> {
    web_sys::window()?.local_storage().ok().flatten()
}

/// The last part of a name typed as a path: a download has only a file name.
fn file_name(name: &str) -> &str {
    name.rsplit(['/', '\\']).find(|s| !s.is_empty()).unwrap_or("grainscope-file")
}

/// The media type of a download, from its name.
fn media_type(name: &str) -> &'static str {
    match name.rsplit('.').next().map(str::to_ascii_lowercase).as_deref() {
        Some("png") => "image/png",
        Some("svg") => "image/svg+xml",
        Some("csv") => "text/csv",
        Some("md") => "text/markdown",
        _ => "application/octet-stream",
    }
}

/// Offers `bytes` to the user as a download named `name`.
pub fn download(name: &str, bytes: &[u8]) -> Result<(), String> {
    let fail = |what: &str, e: JsValue| format!("cannot download {name}: {what} ({e:?})");
    let window = web_sys::window().ok_or_else(|| format!("cannot download {name}: no window"))?;
    let document = window.document().ok_or_else(|| format!("cannot download {name}: no document"))?;
    let parts = js_sys::Array::of1(&js_sys::Uint8Array::from(bytes));
    let options = web_sys::BlobPropertyBag::new();
    options.set_type(media_type(name));
    let blob = web_sys::Blob::new_with_u8_array_sequence_and_options(&parts, &options).map_err(|e| fail("blob", e))?;
    let url = web_sys::Url::create_object_url_with_blob(&blob).map_err(|e| fail("address", e))?;
    let anchor = document
        .create_element("a")
        .map_err(|e| fail("link", e))?
        .dyn_into::<web_sys::HtmlAnchorElement>()
        .map_err(|e| fail("link", e.into()))?;
    anchor.set_href(&url);
    anchor.set_download(file_name(name));
    anchor.click();
    // The browser has taken the data once the click is handled.
    let revoke = Closure::once_into_js(move || {
        let _ = web_sys::Url::revoke_object_url(&url);
    });
    let _ = window.set_timeout_with_callback_and_timeout_and_arguments_0(revoke.unchecked_ref(), 10_000);
    Ok(())
}

/// Reads a picked file's bytes.
async fn read_file(file: web_sys::File) -> Result<Vec<u8>, String> {
    let buffer = wasm_bindgen_futures::JsFuture::from(file.array_buffer())
        .await
        .map_err(|e| format!("cannot read {}: {e:?}", file.name()))?;
    Ok(js_sys::Uint8Array::new(&buffer).to_vec())
}

/// Reads a file the user dropped or picked, as the answer to a pick of `kind`.
async fn answer_for(kind: FileKind, file: web_sys::File) -> Answer {
    let name = file.name();
    match read_file(file).await {
        Ok(bytes) => Answer::Opened(kind, Picked { name, bytes }),
        Err(e) => Answer::Failed(kind, e),
    }
}

impl Platform for WebPlatform {
    /// Files go to the downloads and come from the picker or a drop.
    fn paths(&self) -> bool {
        false
    }

    fn pick_file(&mut self, kind: FileKind) {
        let (answers, wake) = (Rc::clone(&self.answers), Rc::clone(&self.wake));
        let input = web_sys::window()
            .and_then(|w| w.document())
            .and_then(|d| d.create_element("input").ok())
            .and_then(|e| e.dyn_into::<web_sys::HtmlInputElement>().ok());
        let Some(input) = input else {
            answers.borrow_mut().push(Answer::Failed(kind, "the page cannot show a file picker".into()));
            return;
        };
        input.set_type("file");
        let (_, extensions) = kind.filter();
        input.set_accept(&extensions.iter().map(|e| format!(".{e}")).collect::<Vec<_>>().join(","));
        let picked = input.clone();
        let on_change = Closure::once_into_js(move || {
            let file = picked.files().and_then(|f| f.get(0));
            wasm_bindgen_futures::spawn_local(async move {
                let answer = match file {
                    Some(file) => answer_for(kind, file).await,
                    None => Answer::Cancelled,
                };
                answers.borrow_mut().push(answer);
                wake();
            });
        });
        input.set_onchange(Some(on_change.unchecked_ref()));
        input.click();
    }

    fn save_file(&mut self, kind: FileKind, suggested: &str, bytes: Vec<u8>) {
        let answer = match download(suggested, &bytes) {
            Ok(()) => Answer::Saved(kind, format!("{} (downloaded)", file_name(suggested))),
            Err(e) => Answer::Failed(kind, e),
        };
        self.answers.borrow_mut().push(answer);
    }

    fn poll(&mut self) -> Vec<Answer> {
        std::mem::take(&mut *self.answers.borrow_mut())
    }

    fn read(&mut self, name: &str) -> Result<Vec<u8>, String> {
        Err(format!("{name}: a browser cannot read a typed path; open the file with Open… or drop it on the page"))
    }

    fn write(&mut self, name: &str, bytes: &[u8]) -> Result<String, String> {
        download(name, bytes)?;
        Ok(format!("{} (downloaded)", file_name(name)))
    }

    fn write_all(&mut self, _folder: &str, files: &[(String, Vec<u8>)]) -> Result<Vec<String>, String> {
        let mut written = Vec::new();
        for (name, bytes) in files {
            download(name, bytes)?;
            written.push(format!("{} (downloaded)", file_name(name)));
        }
        Ok(written)
    }

    fn load_session(&mut self) -> Restored {
        let fresh = |notice| Restored { session: Default::default(), found: false, notice, may_save: true };
        let Some(storage) = storage() else {
            self.may_save = false;
            return fresh(Some("this browser keeps no storage for the page: the session will not be kept".into()));
        };
        let text = match storage.get_item(SESSION_KEY) {
            Ok(Some(text)) => text,
            Ok(None) => return fresh(None),
            Err(e) => return fresh(Some(format!("the saved session could not be read ({e:?}); started afresh"))),
        };
        match grainscope::session::parse(&text) {
            Ok(session) => Restored { session, found: true, notice: None, may_save: true },
            Err(why) => {
                let why = why.lines().next().unwrap_or_default().to_string();
                let kept = storage.set_item(UNREADABLE_KEY, &text).is_ok();
                let _ = storage.remove_item(SESSION_KEY);
                let aside =
                    if kept { format!(", the old one was kept under \"{UNREADABLE_KEY}\"") } else { String::new() };
                fresh(Some(format!(
                    "the saved session could not be read ({why}); started with default settings{aside}"
                )))
            }
        }
    }

    fn save_session(&mut self, bytes: &[u8]) -> Result<(), String> {
        if !self.may_save {
            return Ok(());
        }
        if bytes.len() > SESSION_LIMIT {
            return Err(format!(
                "the session is {} kB, more than the {} kB the page keeps; clear pins to shrink it",
                bytes.len() / 1000,
                SESSION_LIMIT / 1000
            ));
        }
        let text = std::str::from_utf8(bytes).map_err(|_| "the session is not text".to_string())?;
        let storage = storage().ok_or_else(|| "the browser keeps no storage for this page".to_string())?;
        storage.set_item(SESSION_KEY, text).map_err(|e| format!("the browser refused to keep the session ({e:?})"))
    }

    fn now(&self) -> f64 {
        web_sys::window().and_then(|w| w.performance()).map_or(0.0, |p| p.now() / 1000.0)
    }

    /// The link goes into the address bar (a reload keeps the state, and the
    /// lecturer can copy it from there) and, where the page may write the
    /// clipboard (https, or this machine), onto the clipboard.
    fn share_link(&mut self, query: &str) -> Result<SharedLink, String> {
        let window = web_sys::window().ok_or("no window to give a link")?;
        let location = window.location();
        let page = format!("{}{}", location.origin().unwrap_or_default(), location.pathname().unwrap_or_default());
        let link = format!("{page}{query}");
        if let Ok(history) = window.history() {
            let _ = history.replace_state_with_url(&JsValue::NULL, "", Some(&link));
        }
        let copied = window.is_secure_context() && {
            let _ = window.navigator().clipboard().write_text(&link);
            true
        };
        let said = if copied {
            format!("link copied, and in the address bar: {link}")
        } else {
            format!("link in the address bar (this page may not write the clipboard): {link}")
        };
        Ok(SharedLink { address: link, said })
    }
}

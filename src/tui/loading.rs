//! Scene files are read off the UI thread: the app says which file it
//! waits for, the event loop reads it in a thread and hands it back
//! ([`crate::app::Msg::SceneRead`]).

use std::path::PathBuf;

use crate::app::App;

impl App {
    /// The scene file the UI waits for, if the current entry has not been
    /// read yet: the event loop reads it in a thread and answers with
    /// [`Msg::SceneRead`](crate::app::Msg::SceneRead).
    pub fn scene_to_read(&self) -> Option<(usize, PathBuf)> {
        let entry = self.current_scene()?;
        entry.pending.clone().map(|p| (self.scene, p))
    }

    /// Reads the current scene now, in this thread, if it waits to be read
    /// (what the event loop does in a thread; for tests and tools).
    pub fn read_scene_now(&mut self) {
        if let Some((index, path)) = self.scene_to_read() {
            let read = crate::scenes::read_scene(&path);
            self.scene_read(index, &path, read);
        }
    }

    /// Takes a scene file the event loop read: the entry gets it, and if it
    /// is the current scene its render starts.
    pub fn scene_read(&mut self, index: usize, path: &std::path::Path, read: crate::scenes::Read) {
        let Some(entry) = self.scenes.get_mut(index) else {
            return;
        };
        if entry.finish_loading(path, read) && index == self.scene {
            self.restart();
        }
    }

    /// Scene `index`'s file was edited since it was read: it is read again
    /// (by the event loop, in a thread), and if it is the current scene
    /// its render starts anew on it.
    pub fn scene_edited(&mut self, index: usize) {
        let Some(entry) = self.scenes.get_mut(index) else {
            return;
        };
        entry.read_again();
        // The file is new: what the chapters said of the old one is not
        // known of it.
        self.refusals.retain(|(_, s), _| *s != index);
        self.message = format!(
            "reloading {}: the file changed",
            crate::core::text::escape(&entry.source)
        );
        if index == self.scene {
            self.restart();
        }
    }

    /// The scene chapter `index` opens on: the first time, the chapter's
    /// own scene ([`ChapterInfo::scene`](crate::core::stage::ChapterInfo::scene))
    /// when the list has it; never a scene the chapter is known to refuse
    /// when another one may work (then the first such one). `None`: stay.
    pub fn opening_scene(&self, index: usize) -> Option<usize> {
        let first_time = !self.opened.get(index).copied().unwrap_or(false);
        let own = self.chapters.get(index)?.info().scene;
        if let (true, Some(name)) = (first_time, own) {
            let found = self.scenes.iter().position(|e| e.stem() == name);
            if let Some(i) = found.filter(|i| self.problem_in(index, *i).is_none()) {
                return Some(i);
            }
        }
        let refused_here = self.problem_in(index, self.scene).is_some();
        if !refused_here {
            return None;
        }
        (0..self.scenes.len()).find(|i| self.problem_in(index, *i).is_none())
    }

    /// The current chapter refused the current scene (`message`): known
    /// from now on. If the scene came with a switch to this chapter (the
    /// user did not pick it here), the chapter moves to the first scene it
    /// is not known to refuse, and says so: switching chapters never
    /// leaves one on a scene it refuses while another may work.
    pub fn refused(&mut self, message: String) {
        let (chapter, refused) = (self.chapter, self.scene);
        self.refusals.insert((chapter, refused), message);
        if !self.scene_came_with_chapter {
            return;
        }
        let other = (0..self.scenes.len()).find(|i| self.problem_in(chapter, *i).is_none());
        if let Some(i) = other {
            self.scene = i;
            self.restart();
            let name = |i: usize| {
                self.scenes.get(i).map_or(String::new(), |e| {
                    crate::core::text::escape(e.stem()).into_owned()
                })
            };
            self.message = format!(
                "this chapter cannot render {}: opened {} instead",
                name(refused),
                name(i)
            );
        }
    }
}

// The page's files and config folder. A file written for the user is downloaded (a Blob and an
// <a download>) and recorded in window.foldlabDownloads (name, size, first 64 bytes), where a
// test reads it. A file to open comes from an <input type=file>: its bytes are copied into
// /uploads by Module.foldlabFiles.receive(name, bytes), the one entry point of picked files
// (the page's ?pick=URL answers the picker through it in tests). The config folder is copied
// from localStorage at start and back after every frame: one key per file, "foldlab:" and its
// path in the folder, the bytes as a string of char codes 0-255.
#include <emscripten/emscripten.h>

#include <string>

#include "app/gui/config_store.hpp"
#include "app/gui/file_transfer.hpp"

namespace foldlab::gui {
namespace {

EM_JS(int, download_file, (const char* path), {
  try {
    const file = UTF8ToString(path);
    const bytes = FS.readFile(file);
    const name = file.substring(file.lastIndexOf("/") + 1);
    const url = URL.createObjectURL(new Blob([bytes], {
      type:
        "application/octet-stream"
    }));
    const link = document.createElement("a");
    link.href = url;
    link.download = name;
    link.style.display = "none";
    document.body.appendChild(link);
    link.click();
    link.remove();
    setTimeout(
        function() { URL.revokeObjectURL(url); }, 60000);
    let head = "";
    for (let i = 0; i < Math.min(bytes.length, 64); ++i) {
      head += String.fromCharCode(bytes[i]);
    }
    (window.foldlabDownloads = window.foldlabDownloads || [])
        .push({name : name, size : bytes.length, head : head});
    return 1;
  } catch (e) {
    err("download: " + e);
    return 0;
  }
});

// JavaScript, which clang-format would read as C++.
// clang-format off
EM_JS(void, install_file_picker, (), {
  if (Module.foldlabFiles) {
    return;
  }
  Module.foldlabFiles = {
    picked : [],
    // A picked file's name and bytes (Uint8Array): copied into /uploads for the explorer,
    // which takes it at its next frame.
    receive : function(name, bytes) {
      // No folders in a name, neither / nor the backslash (char code 92).
      let safe = String(name).split("/").join("_").split(String.fromCharCode(92)).join("_");
      safe = safe || "file";
      if (safe.charAt(0) == ".") {
        safe = "_" + safe;  // never hidden, never ".."
      }
      FS.mkdirTree("/uploads");
      FS.writeFile("/uploads/" + safe, bytes);
      this.picked.push("/uploads/" + safe);
      Module.foldlabInputSeen = true;  // wakes a resting explorer
    },
    pick : function(accept) {
      const files = this;
      if (Module.foldlabPickQueue && Module.foldlabPickQueue.length) {
        const next = Module.foldlabPickQueue.shift();  // a test's answer (index.html, ?pick=URL)
        files.receive(next.name, next.bytes);
        return;
      }
      let input = document.getElementById("foldlab-file-input");
      if (!input) {
        input = document.createElement("input");
        input.type = "file";
        input.id = "foldlab-file-input";
        input.style.display = "none";
        document.body.appendChild(input);
      }
      input.accept = accept;
      input.value = "";
      input.onchange = function() {
        const file = input.files && input.files[0];
        if (!file) {
          return;
        }
        file.arrayBuffer()
            .then(function(buffer) { files.receive(file.name, new Uint8Array(buffer)); })
            .catch(function(e) { err(file.name + ": " + e); });
      };
      // A browser opens the picker only shortly after a click or key: the frame that handles
      // the button's click follows it within milliseconds.
      input.click();
    }
  };
});
// clang-format on
EM_JS(void, open_file_picker, (const char* accept),
      { Module.foldlabFiles.pick(UTF8ToString(accept)); });

class BrowserFiles final : public FileTransfer {
 public:
  BrowserFiles() { install_file_picker(); }
  bool browses_folders() const override { return false; }
  std::filesystem::path outbox() const override { return "/downloads"; }
  bool deliver(const std::filesystem::path& path) override {
    return download_file(path.c_str()) != 0;
  }
  void pick(const std::vector<std::string>& extensions) override {
    std::string accept;
    for (const std::string& extension : extensions) {
      accept += (accept.empty() ? "" : ",") + extension;
    }
    open_file_picker(accept.c_str());
  }
  std::optional<std::filesystem::path> take_picked() override {
    const std::string path = emscripten_run_script_string(
        "(Module.foldlabFiles && Module.foldlabFiles.picked.shift()) || ''");
    if (path.empty()) {
      return std::nullopt;
    }
    return std::filesystem::path(path);
  }
};

// localStorage, not IDBFS: a write is stored when setItem returns (IDBFS's syncfs is
// asynchronous, so a tab closed during one loses it), and the start reads it at once, with no
// asynchronous step before main. The files are a few KB, far below its 5 MB.
EM_JS(void, restore_folder, (const char* folder), {
  let storage;
  try {
    storage = window.localStorage;
  } catch (e) {
    return;  // storage blocked (the browser's privacy settings): nothing was kept
  }
  const root = UTF8ToString(folder);
  const kept = Module.foldlabKept = {};
  for (let i = 0; storage && i < storage.length; ++i) {
    const key = storage.key(i);
    if (!key.startsWith("foldlab:")) {
      continue;
    }
    const name = key.slice("foldlab:".length);
    if (name.split("/").some(
            function(part) { return part == "" || part == "." || part == ".."; })) {
      continue;
    }
    const text = storage.getItem(key);
    const bytes = new Uint8Array(text.length);
    for (let j = 0; j < text.length; ++j) {
      bytes[j] = text.charCodeAt(j) & 255;
    }
    const path = root + "/" + name;
    FS.mkdirTree(path.substring(0, path.lastIndexOf("/")));
    FS.writeFile(path, bytes);
    const stat = FS.stat(path);
    kept[name] = stat.mtime.getTime() + ":" + stat.size;
  }
});

// 1 when storage refused a file for the first time (full, or blocked).
EM_JS(int, keep_folder, (const char* folder), {
  let storage;
  try {
    storage = window.localStorage;
  } catch (e) {
    storage = null;
  }
  const root = UTF8ToString(folder);
  const kept = Module.foldlabKept || (Module.foldlabKept = {});
  const seen = {};
  let refused = 0;
  const walk = function(dir, prefix) {
    let names;
    try {
      names = FS.readdir(dir);
    } catch (e) {
      return;
    }
    names.forEach(function(name) {
      if (name == "." || name == "..") {
        return;
      }
      const path = dir + "/" + name;
      const key = prefix + name;
      const stat = FS.stat(path);
      if (FS.isDir(stat.mode)) {
        walk(path, key + "/");
        return;
      }
      const signature = stat.mtime.getTime() + ":" + stat.size;
      seen[key] = true;
      if (kept[key] == signature) {
        return;
      }
      const bytes = FS.readFile(path);
      let text = "";
      for (let i = 0; i < bytes.length; i += 8192) {
        text += String.fromCharCode.apply(null, bytes.subarray(i, i + 8192));
      }
      try {
        storage.setItem("foldlab:" + key, text);
        kept[key] = signature;
      } catch (e) {
        if (!Module.foldlabStorageRefused) {
          Module.foldlabStorageRefused = true;
          refused = 1;
        }
      }
    });
  };
  walk(root, "");
  Object.keys(kept).forEach(function(key) {
    if (!seen[key]) {
      if (storage) {
        storage.removeItem("foldlab:" + key);
      }
      delete kept[key];
    }
  });
  return refused;
});

class BrowserStorage final : public ConfigStore {
 public:
  void restore(const std::filesystem::path& folder) override { restore_folder(folder.c_str()); }
  std::optional<std::string> keep(const std::filesystem::path& folder) override {
    if (keep_folder(folder.c_str()) != 0) {
      return "The browser's storage did not take the session or a preset (full, or switched off "
             "for this site): what changed is not kept after the page closes.";
    }
    return std::nullopt;
  }
  bool owns_folder() const override { return true; }
};

}  // namespace

std::unique_ptr<FileTransfer> make_file_transfer() {
  return std::make_unique<BrowserFiles>();
}

std::unique_ptr<ConfigStore> make_config_store() {
  return std::make_unique<BrowserStorage>();
}

}  // namespace foldlab::gui

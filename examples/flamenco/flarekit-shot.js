// Flamenco 3 job type (a template, not run by the tests): put this file in the Manager's
// scripts/ folder. The frame range is cut into chunks; each task runs flarekit on exactly its
// frames (--frames A-B), every frame written atomically and bit-identical however the shot is
// chunked, so a failed task can be re-queued safely.
const JOB_TYPE = {
  label: "flarekit shot",
  settings: [
    { key: "plate", type: "string", subtype: "file_path", required: true,
      description: "Plate frame pattern, e.g. /shots/sh010/plate/sh010.####.exr" },
    { key: "output", type: "string", subtype: "file_path", required: true,
      description: "Output frame pattern, e.g. /shots/sh010/flare/sh010.####.exr" },
    { key: "frame_start", type: "int32", required: true, default: 1001 },
    { key: "frame_end", type: "int32", required: true, default: 1240 },
    { key: "chunk_size", type: "int32", default: 10, description: "Frames per task" },
    { key: "options", type: "string", default: "--preset tanczos-classic",
      description: "Further flarekit apply options (--light-track, --matte, ...)" },
  ],
};

function compileJob(job) {
  const s = job.settings;
  const extra = s.options.split(" ").filter((word) => word.length > 0);
  for (let start = s.frame_start; start <= s.frame_end; start += s.chunk_size) {
    const end = Math.min(start + s.chunk_size - 1, s.frame_end);
    const task = author.Task(`flare-${start}-${end}`, "misc");
    task.addCommand(author.Command("exec", {
      exe: "flarekit",
      args: ["apply", s.plate, "-o", s.output, ...extra, "--frames", `${start}-${end}`],
    }));
    job.addTask(task);
  }
}

using System;
using System.Runtime.InteropServices;
using System.Text;

namespace NavLink
{
    public sealed partial class World
    {
        /// <summary>The null carrier and no flags (for a raw Native.nl_navmesh_load; LoadNavmesh takes carrier
        /// and sameLevel instead).</summary>
        public static NavmeshLoadDef DefaultNavmeshLoadDef() { LibraryCheck.EnsureLoaded(); return Native.nl_default_navmesh_load_def(); }

        /// <summary>The navmesh, its links (generated and manual, in GetLinks order) and what they were made for,
        /// as a navmesh file's bytes. InvalidArgument for a navmesh with cross links (a file holds one navmesh's
        /// own links).</summary>
        public unsafe byte[] SaveNavmesh(NavmeshId navmesh)
        {
            using (var w = Enter())
            {
                while (true)
                {
                    UIntPtr size;
                    Status.Check(Native.nl_navmesh_save(w.Pointer, navmesh, null, UIntPtr.Zero, &size));
                    var buffer = new byte[(ulong)size];
                    StatusCode status;
                    fixed (byte* b = buffer)
                        status = Native.nl_navmesh_save(w.Pointer, navmesh, b, (UIntPtr)buffer.Length, &size);
                    if (Status.IsBufferTooSmall(status)) continue;  // links changed
                    Status.Check(status);
                    if ((ulong)size < (ulong)buffer.Length) Array.Resize(ref buffer, (int)(ulong)size);
                    return buffer;
                }
            }
        }

        /// <summary>SaveNavmesh written to the file at path, whole or not at all. IoError: cannot write.</summary>
        public unsafe void SaveNavmeshFile(NavmeshId navmesh, string path)
        {
            if (path == null) throw new ArgumentNullException("path");
            byte[] utf8 = Utf8.EncodeZ(path);
            fixed (byte* p = utf8)
            using (var w = Enter())
                Status.Check(Native.nl_navmesh_save_file(w.Pointer, navmesh, p));
        }

        /// <summary>One tile of a tiled navmesh as a tile's file's bytes: the tile's polygons as built or added, the
        /// generated links it owns (those that start on it, wherever they end), what it was made for, and its
        /// content hash (GetTileHash); host links are not in it (SaveNavmesh saves a whole navmesh with them).
        /// Load the first tile of a world with LoadNavmesh (a tiled navmesh of that tile) and the others with
        /// AddTileBytes, in any order: the navmesh and links are those the tiles were saved from. NavLinkException
        /// with NotFound when no tile is loaded there, InvalidArgument for a navmesh that is not tiled or rides a
        /// movable mesh (save it whole).</summary>
        public unsafe byte[] SaveTile(NavmeshId navmesh, TileCoord tile)
        {
            using (var w = Enter())
            {
                while (true)
                {
                    UIntPtr size;
                    Status.Check(Native.nl_navmesh_save_tile(w.Pointer, navmesh, tile, null, UIntPtr.Zero, &size));
                    var buffer = new byte[(ulong)size];
                    StatusCode status;
                    fixed (byte* b = buffer)
                        status = Native.nl_navmesh_save_tile(w.Pointer, navmesh, tile, b, (UIntPtr)buffer.Length, &size);
                    if (Status.IsBufferTooSmall(status)) continue;  // the tile or its links changed
                    Status.Check(status);
                    if ((ulong)size < (ulong)buffer.Length) Array.Resize(ref buffer, (int)(ulong)size);
                    return buffer;
                }
            }
        }

        /// <summary>SaveTile written to the file at path, whole or not at all. IoError: cannot write.</summary>
        public unsafe void SaveTileFile(NavmeshId navmesh, TileCoord tile, string path)
        {
            if (path == null) throw new ArgumentNullException("path");
            byte[] utf8 = Utf8.EncodeZ(path);
            fixed (byte* p = utf8)
            using (var w = Enter())
                Status.Check(Native.nl_navmesh_save_tile_file(w.Pointer, navmesh, tile, p));
        }

        /// <summary>Adds the tile a tile's file's bytes hold (SaveTile) to a tiled navmesh, with its links, as AddTile
        /// adds a tile; no link is generated: a link to a tile not loaded waits, out of every path, until that tile
        /// is added. VersionMismatch (not a NavLink navmesh file, or a newer format), ParseError (truncated or
        /// corrupted), InvalidArgument (a whole navmesh's file; a tile of another grid or agent type, or made with
        /// another builder, builder settings or link settings than the navmesh; a tile already loaded there;
        /// polygons or links that do not fit). Nothing changed on failure.</summary>
        public unsafe void AddTileBytes(NavmeshId navmesh, ReadOnlySpan<byte> data)
        {
            fixed (byte* d = &MemoryMarshal.GetReference(data))
            using (var w = Enter())
                Status.Check(Native.nl_navmesh_add_tile_bytes(w.Pointer, navmesh, d, (UIntPtr)data.Length));
        }

        /// <summary>AddTileBytes from the file at path; also NotFound (no such file) and IoError.</summary>
        public unsafe void AddTileFile(NavmeshId navmesh, string path)
        {
            if (path == null) throw new ArgumentNullException("path");
            byte[] utf8 = Utf8.EncodeZ(path);
            fixed (byte* p = utf8)
            using (var w = Enter())
                Status.Check(Native.nl_navmesh_add_tile_file(w.Pointer, navmesh, p));
        }

        /// <summary>The content hash of the tile at that place of a tiled navmesh's grid (loaded or not), from what
        /// the world holds now: the level's triangles in the columns the tile, its links and its neighbours'
        /// borders reach, the builder and its settings, the link settings and the body. A tile's file records the
        /// hash it was saved with (NavmeshFileInfo.ContentHash): a bake skips a tile whose hash it holds. Never 0.
        /// InvalidArgument for a navmesh that is not tiled.</summary>
        public unsafe ulong GetTileHash(NavmeshId navmesh, TileCoord tile)
        {
            ulong hash;
            using (var w = Enter()) Status.Check(Native.nl_navmesh_get_tile_hash(w.Pointer, navmesh, tile, &hash));
            return hash;
        }

        private static NavmeshLoadDef LoadDef(MeshId carrier, bool sameLevel)
        {
            NavmeshLoadDef def = Native.nl_default_navmesh_load_def();
            def.Carrier = carrier;
            def.Flags = sameLevel ? NavmeshLoadFlags.SameLevel : NavmeshLoadFlags.None;
            return def;
        }

        /// <summary>Adds the navmesh and its links held in a navmesh file's bytes (new ids); a tile's file (SaveTile)
        /// makes a tiled navmesh of that one tile, which AddTileBytes grows. carrier: for a file whose navmesh rode
        /// a movable mesh (NavmeshFileInfo.RidesCarrier), the movable mesh it rides now; sameLevel: refuse
        /// (InvalidArgument) a file baked from other level geometry than the world holds now.
        /// VersionMismatch (not a NavLink navmesh file, or a newer format), ParseError (truncated or corrupted),
        /// InvalidArgument (a carrier for a file that rode none or none for one that did; polygons or links
        /// that do not fit). Nothing is added on failure.</summary>
        public unsafe NavmeshId LoadNavmesh(ReadOnlySpan<byte> data, MeshId carrier = default(MeshId), bool sameLevel = false)
        {
            NavmeshLoadDef def = LoadDef(carrier, sameLevel);
            NavmeshId id;
            fixed (byte* d = &MemoryMarshal.GetReference(data))
            using (var w = Enter())
                Status.Check(Native.nl_navmesh_load(w.Pointer, d, (UIntPtr)data.Length, &def, &id));
            return id;
        }

        /// <summary>LoadNavmesh from the file at path; also NotFound (no such file) and IoError.</summary>
        public unsafe NavmeshId LoadNavmeshFile(string path, MeshId carrier = default(MeshId), bool sameLevel = false)
        {
            if (path == null) throw new ArgumentNullException("path");
            byte[] utf8 = Utf8.EncodeZ(path);
            NavmeshLoadDef def = LoadDef(carrier, sameLevel);
            NavmeshId id;
            fixed (byte* p = utf8)
            using (var w = Enter())
                Status.Check(Native.nl_navmesh_load_file(w.Pointer, p, &def, &id));
            return id;
        }

        /// <summary>Reads a navmesh file's bytes without loading it (no world needed): what it holds, and in
        /// madeForJson what it was made for as a JSON object ({"builder", "builder_settings", "link_settings",
        /// "link_plugins", "level_hash", "writer"}). VersionMismatch (not a NavLink navmesh file, or a newer format),
        /// ParseError (truncated or corrupted).</summary>
        public static unsafe NavmeshFileInfo DescribeNavmeshFile(ReadOnlySpan<byte> data, out string madeForJson)
        {
            LibraryCheck.EnsureLoaded();
            var info = default(NavmeshFileInfo);
            info.Size = (uint)sizeof(NavmeshFileInfo);
            fixed (byte* d = &MemoryMarshal.GetReference(data))
            {
                UIntPtr length;
                Status.Check(Native.nl_navmesh_file_describe(d, (UIntPtr)data.Length, &info, null, UIntPtr.Zero, &length));
                var buffer = new byte[(ulong)length + 1];
                fixed (byte* b = buffer)
                    Status.Check(Native.nl_navmesh_file_describe(d, (UIntPtr)data.Length, null, b, (UIntPtr)buffer.Length,
                                                                 &length));
                madeForJson = Encoding.UTF8.GetString(buffer, 0, (int)(ulong)length);
            }
            return info;
        }

        /// <summary>DescribeNavmeshFile without the made-for JSON.</summary>
        public static unsafe NavmeshFileInfo DescribeNavmeshFile(ReadOnlySpan<byte> data)
        {
            LibraryCheck.EnsureLoaded();
            var info = default(NavmeshFileInfo);
            info.Size = (uint)sizeof(NavmeshFileInfo);
            fixed (byte* d = &MemoryMarshal.GetReference(data))
                Status.Check(Native.nl_navmesh_file_describe(d, (UIntPtr)data.Length, &info, null, UIntPtr.Zero, null));
            return info;
        }
    }
}

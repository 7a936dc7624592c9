using System;
using System.Collections.Generic;
using System.Runtime.InteropServices;

namespace NavLink
{
    /// <summary>What a loaded plugin is (nl_plugin_description, strings copied).</summary>
    public sealed class PluginSummary
    {
        public PluginId Id;
        public string Name;
        public string Version;
        public string Description;
        public PluginKinds Kinds;
        public bool Builtin;
        public uint AbiVersion;
    }

    public sealed partial class World
    {
        // Entry delegates handed to nl_plugin_register: the plugin's functions stay callable while the
        // world lives, so the delegates must too.
        private readonly List<NativeCallbacks.PluginEntryFn> registeredEntries = new List<NativeCallbacks.PluginEntryFn>();

        /// <summary>Loads a plugin library (its nl_plugin_entry) into the world.</summary>
        public unsafe PluginId LoadPlugin(string path)
        {
            byte[] utf8 = Utf8.EncodeZ(path);
            PluginId id;
            fixed (byte* p = utf8)
            using (var w = Enter())
                Status.Check(Native.nl_plugin_load(w.Pointer, p, &id));
            return id;
        }

        /// <summary>Registers a plugin compiled into the host through its entry function. For IL2CPP the
        /// entry (and every function it hands over) must wrap a static [MonoPInvokeCallback] method.</summary>
        public unsafe PluginId RegisterPlugin(NativeCallbacks.PluginEntryFn entry)
        {
            if (entry == null) throw new ArgumentNullException("entry");
            PluginId id;
            lock (registeredEntries) registeredEntries.Add(entry);
            using (var w = Enter())
                Status.Check(Native.nl_plugin_register(w.Pointer, Marshal.GetFunctionPointerForDelegate(entry), &id));
            return id;
        }

        public unsafe PluginSummary DescribePlugin(PluginId plugin)
        {
            PluginDescription d = Native.nl_plugin_description_init();
            using (var w = Enter()) Status.Check(Native.nl_plugin_get_description(w.Pointer, plugin, &d));
            return new PluginSummary
            {
                Id = plugin,
                Name = Utf8.Decode(d.Name),
                Version = Utf8.Decode(d.Version),
                Description = Utf8.Decode(d.Description),
                Kinds = d.Kinds,
                Builtin = d.Builtin != 0,
                AbiVersion = d.AbiVersion,
            };
        }

        /// <summary>The world's plugins, built-in ones first.</summary>
        public unsafe PluginId[] GetPlugins()
        {
            using (var w = Enter())
            {
                IntPtr world = w.Pointer;
                return ListTwoCall<PluginId>((buffer, capacity, count) =>
                    Native.nl_world_get_plugins(world, (PluginId*)buffer, capacity, count));
            }
        }
    }
}

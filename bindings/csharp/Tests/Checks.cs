using System;
using NavLink;

namespace NavLink.Tests
{
    // Counts checks: each That() is one check; a section that throws counts one failure and stops there.
    internal sealed class Checks
    {
        public int Passed;
        public int Failed;
        private string section = "";

        public void Run(string name, Action body)
        {
            section = name;
            Console.WriteLine("-- " + name);
            try
            {
                body();
            }
            catch (Exception e)
            {
                Fail("threw " + e.GetType().Name + ": " + e.Message + "\n" + e.StackTrace);
            }
        }

        public bool That(bool ok, string what)
        {
            if (ok) ++Passed;
            else Fail(what);
            return ok;
        }

        public void Near(float actual, float expected, float tolerance, string what)
        {
            That(Math.Abs(actual - expected) <= tolerance, what + ": " + actual + ", expected " + expected + " +- " + tolerance);
        }

        /// <summary>The call must throw NavLinkException whose status has detailBit and whose message
        /// (the library's last error) contains messagePart.</summary>
        public void Throws(StatusCode detailBit, string messagePart, Action call, string what)
        {
            try
            {
                call();
                Fail(what + ": no exception");
            }
            catch (NavLinkException e)
            {
                That(NavLink.Status.Failed(e.StatusCode) && e.Has(detailBit), what + ": status " + e.StatusCode + " lacks " + detailBit);
                That(e.Message.Contains(messagePart), what + ": message '" + e.Message + "' lacks '" + messagePart + "'");
            }
        }

        /// <summary>A raw status must be a failure with detailBit, and the last error must name messagePart.</summary>
        public void Status(StatusCode status, StatusCode detailBit, string messagePart, string what)
        {
            That(NavLink.Status.Failed(status) && NavLink.Status.Has(status, detailBit),
                 what + ": status " + status + ", expected a failure with " + detailBit);
            string message = NavLink.Status.LastErrorMessage();
            That(message.Contains(messagePart), what + ": message '" + message + "' lacks '" + messagePart + "'");
        }

        private void Fail(string what)
        {
            ++Failed;
            Console.WriteLine("FAIL [" + section + "] " + what);
        }
    }
}
